# Install rules and the CMake package: `cmake --install <build> --prefix <p>` puts the
# `cambrian` executable, the public headers (with the generated cambrian/version.hpp), the static
# subsystem libraries and an exported target set under <p>, and `find_package(cambrian)` finds
# them (docs/embedding.md). Included last by the top-level CMakeLists.txt, after src/.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(CAMBRIAN_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/cambrian
    CACHE STRING "Where cambrianConfig.cmake is installed, relative to the prefix")

# public headers, and the version header generated into the build tree
install(DIRECTORY include/cambrian DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/generated/cambrian/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cambrian)

# the executable
if(TARGET cambrian)
  install(TARGETS cambrian RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

# the subsystem libraries, exported as cambrian::<module> (the names the build tree's aliases use)
set(cambrian_exported_modules "")
foreach(module ${CAMBRIAN_MODULES})
  if(TARGET cambrian_${module} AND NOT module STREQUAL "app")
    list(APPEND cambrian_exported_modules cambrian_${module})
    set_target_properties(cambrian_${module} PROPERTIES EXPORT_NAME ${module})
  endif()
endforeach()

# cambrian::cambrian: the one target embedders link (every subsystem library above)
add_library(cambrian_cambrian INTERFACE)
add_library(cambrian::cambrian ALIAS cambrian_cambrian)
set_target_properties(cambrian_cambrian PROPERTIES EXPORT_NAME cambrian)
target_link_libraries(cambrian_cambrian INTERFACE ${cambrian_exported_modules})

# helper targets the libraries link (flags are link-only; Bullet and Random123 wrap system
# packages that cambrianConfig.cmake finds again on the embedder's machine)
set_target_properties(cambrian_flags PROPERTIES EXPORT_NAME flags)
set_target_properties(cambrian_bullet PROPERTIES EXPORT_NAME bullet)
set_target_properties(cambrian_random123 PROPERTIES EXPORT_NAME random123)
set_target_properties(cambrian_odeint PROPERTIES EXPORT_NAME odeint)

install(TARGETS ${cambrian_exported_modules} cambrian_cambrian cambrian_flags cambrian_bullet
                cambrian_random123 cambrian_odeint
        EXPORT cambrianTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT cambrianTargets NAMESPACE cambrian:: DESTINATION ${CAMBRIAN_INSTALL_CMAKEDIR})

# cambrianConfig.cmake (finds the dependencies again) and its version file
configure_package_config_file(
  ${PROJECT_SOURCE_DIR}/cmake/cambrianConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cambrianConfig.cmake
  INSTALL_DESTINATION ${CAMBRIAN_INSTALL_CMAKEDIR})
# 0.x: a minor version may break the API, so only the same minor version is compatible
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cambrianConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cambrianConfig.cmake
              ${PROJECT_BINARY_DIR}/cambrianConfigVersion.cmake
        DESTINATION ${CAMBRIAN_INSTALL_CMAKEDIR})
