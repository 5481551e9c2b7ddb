# The version and git hash compiled into the binary and written into every history file: the
# hash is taken at every build (cmake/CambrianGitHash.cmake), not once at configure time, so a
# rebuilt binary names its own commit.
set(CAMBRIAN_VERSION_HEADER ${PROJECT_BINARY_DIR}/generated/cambrian/version.hpp)
set(cambrian_git_hash_args
    -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DINPUT=${PROJECT_SOURCE_DIR}/cmake/version.hpp.in
    -DOUTPUT=${CAMBRIAN_VERSION_HEADER} -DPROJECT_VERSION=${PROJECT_VERSION})
execute_process(COMMAND ${CMAKE_COMMAND} ${cambrian_git_hash_args} -P
                        ${PROJECT_SOURCE_DIR}/cmake/CambrianGitHash.cmake)
add_custom_target(
  cambrian_version
  COMMAND ${CMAKE_COMMAND} ${cambrian_git_hash_args} -P
          ${PROJECT_SOURCE_DIR}/cmake/CambrianGitHash.cmake
  BYPRODUCTS ${CAMBRIAN_VERSION_HEADER}
  COMMENT "The git hash into cambrian/version.hpp"
  VERBATIM)
