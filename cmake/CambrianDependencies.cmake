# Dependencies, all from Debian packages (jobs/setup/install-deps.sh installs them).

find_package(PkgConfig REQUIRED)

# Bullet (libbullet-dev): rigid-body and Featherstone multibody dynamics
if(CAMBRIAN_BULLET_DOUBLE)
  pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)
else()
  pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet)
endif()
add_library(cambrian_bullet INTERFACE)
target_link_libraries(cambrian_bullet INTERFACE PkgConfig::BULLET)
# Bullet's pkg-config lists only the 2.x libraries; the multibody code lives in BulletDynamics
set_property(GLOBAL APPEND PROPERTY PACKAGES_FOUND Bullet)

# MPI (libopenmpi-dev): rank 0 breeds, the other ranks evaluate
find_package(MPI REQUIRED COMPONENTS C)
set_package_properties(MPI PROPERTIES TYPE REQUIRED PURPOSE "rank 0 breeds, workers evaluate")

# HDF5 (libhdf5-dev, serial): history and checkpoint files
set(HDF5_PREFER_PARALLEL OFF)
find_package(HDF5 REQUIRED COMPONENTS C)
set_package_properties(HDF5 PROPERTIES TYPE REQUIRED PURPOSE "history.h5 and checkpoint.h5")

# Boost.Program_options (libboost-program-options-dev): command line and INI experiment files
find_package(Boost 1.74 REQUIRED COMPONENTS program_options)
set_package_properties(Boost PROPERTIES TYPE REQUIRED PURPOSE "command line and INI files")

# Boost.Odeint (header-only, in the same Boost headers): the chaotic controllers' integration
find_path(ODEINT_INCLUDE_DIR boost/numeric/odeint/stepper/runge_kutta4.hpp
          HINTS ${Boost_INCLUDE_DIRS} REQUIRED)
add_library(cambrian_odeint INTERFACE)
target_include_directories(cambrian_odeint SYSTEM INTERFACE ${ODEINT_INCLUDE_DIR})

# Random123 (librandom123-dev, header-only): counter-based Philox generator
find_path(RANDOM123_INCLUDE_DIR Random123/philox.h REQUIRED)
add_library(cambrian_random123 INTERFACE)
target_include_directories(cambrian_random123 SYSTEM INTERFACE ${RANDOM123_INCLUDE_DIR})

if(CAMBRIAN_BUILD_TESTS)
  # GoogleTest (googletest / libgtest-dev): the C++ test suite
  find_package(GTest 1.10 REQUIRED)
  set_package_properties(GTest PROPERTIES TYPE REQUIRED PURPOSE "unit and integration tests")
endif()
