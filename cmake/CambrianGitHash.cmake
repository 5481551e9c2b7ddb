# Run at every build (cmake -P): writes the commit being built into cambrian/version.hpp, with
# "-dirty" when tracked files differ from it, so a history names the code that wrote it. The
# file is rewritten only when that changes (configure_file), so nothing else recompiles.
# -DSOURCE_DIR, -DINPUT (version.hpp.in), -DOUTPUT, -DPROJECT_VERSION
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE CAMBRIAN_GIT_HASH OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET RESULT_VARIABLE git_result)
if(NOT git_result EQUAL 0 OR CAMBRIAN_GIT_HASH STREQUAL "")
  set(CAMBRIAN_GIT_HASH "unknown")
else()
  execute_process(COMMAND git status --porcelain --untracked-files=no
                  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE changes ERROR_QUIET)
  if(NOT changes STREQUAL "")
    string(APPEND CAMBRIAN_GIT_HASH "-dirty")
  endif()
endif()
configure_file(${INPUT} ${OUTPUT} @ONLY)
