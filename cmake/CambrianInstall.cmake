# Install rules (the executable and public headers); completed with a package config in the
# shipping work (docs/design.md).
include(GNUInstallDirs)
install(DIRECTORY include/cambrian DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET cambrian)
  install(TARGETS cambrian RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
