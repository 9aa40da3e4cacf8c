# All third-party dependencies come from Debian packages (scripts/install-deps.sh); nothing is
# downloaded at build time.  Each imported target is used only by the modules docs/architecture.md allows.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(Threads REQUIRED)

# Spectra (header only, libspectra-dev)
find_path(SPECTRA_INCLUDE_DIR Spectra/SymEigsShiftSolver.h REQUIRED)
add_library(seflex::spectra INTERFACE IMPORTED)
target_include_directories(seflex::spectra INTERFACE ${SPECTRA_INCLUDE_DIR})

# METIS (libmetis-dev)
find_path(METIS_INCLUDE_DIR metis.h REQUIRED)
find_library(METIS_LIBRARY metis REQUIRED)
add_library(seflex::metis INTERFACE IMPORTED)
target_include_directories(seflex::metis INTERFACE ${METIS_INCLUDE_DIR})
target_link_libraries(seflex::metis INTERFACE ${METIS_LIBRARY})

# ARPACK (libarpack2-dev)
find_library(ARPACK_LIBRARY arpack REQUIRED)
add_library(seflex::arpack INTERFACE IMPORTED)
target_link_libraries(seflex::arpack INTERFACE ${ARPACK_LIBRARY})

# CHOLMOD (libsuitesparse-dev), supernodal Cholesky on BLAS/LAPACK
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSE_CONFIG_LIBRARY suitesparseconfig REQUIRED)
find_package(BLAS REQUIRED)
find_package(LAPACK REQUIRED)
add_library(seflex::cholmod INTERFACE IMPORTED)
target_include_directories(seflex::cholmod INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(seflex::cholmod INTERFACE ${CHOLMOD_LIBRARY} ${SUITESPARSE_CONFIG_LIBRARY} ${LAPACK_LIBRARIES} ${BLAS_LIBRARIES})

# gmsh C API (libgmsh-dev): compiled against gmshc.h, but not linked: io/src/gmsh_api.cpp loads the
# library with dlopen at the first gmsh read, so the ~90 libraries libgmsh brings are not linked
# into every seflex command at start-up (docs/benchmarks.md, "Start-up").
find_path(GMSH_INCLUDE_DIR gmshc.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)  # present at run time (dlopen of its soname)
add_library(seflex::gmsh INTERFACE IMPORTED)
target_include_directories(seflex::gmsh INTERFACE ${GMSH_INCLUDE_DIR})
target_link_libraries(seflex::gmsh INTERFACE ${CMAKE_DL_LIBS})

# nettle (nettle-dev): SHA-256 of superelement files and of the models they come from (io/src/sha256.cpp)
find_path(NETTLE_INCLUDE_DIR nettle/sha2.h REQUIRED)
find_library(NETTLE_LIBRARY nettle REQUIRED)
add_library(seflex::nettle INTERFACE IMPORTED)
target_include_directories(seflex::nettle INTERFACE ${NETTLE_INCLUDE_DIR})
target_link_libraries(seflex::nettle INTERFACE ${NETTLE_LIBRARY})

# VTK 9 (libvtk9-dev): only what the XML writers need, linked by the VTK plugin alone (io/vtk_plugin/,
# libseflex_vtk.so, loaded by io at the first .vtu written) and by the tests that read VTK files back
find_package(VTK 9 REQUIRED COMPONENTS CommonCore CommonDataModel IOXML)

# yaml-cpp (libyaml-cpp-dev): scene files
find_package(yaml-cpp REQUIRED)

if(SEFLEX_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()

# Distributed backend (parallel/): PETSc + SLEPc (petsc-dev, slepc-dev, MUMPS inside PETSc) and MPI
# (mpi-default-dev). SEFLEX_MPI defaults to ON where all of them are found, OFF otherwise; ON without
# them is an error. Only parallel/ and the command-line front end use these targets.
find_package(PkgConfig QUIET)
set(SEFLEX_MPI_FOUND OFF)
if(PkgConfig_FOUND)
  pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc)
  pkg_check_modules(SLEPC QUIET IMPORTED_TARGET SLEPc)
  find_package(MPI QUIET COMPONENTS C)
  if(PETSC_FOUND AND SLEPC_FOUND AND MPI_C_FOUND)
    set(SEFLEX_MPI_FOUND ON)
  endif()
endif()
option(SEFLEX_MPI "Build the distributed PETSc/SLEPc backend (seflex modes/reduce --backend slepc)" ${SEFLEX_MPI_FOUND})
if(SEFLEX_MPI)
  if(NOT SEFLEX_MPI_FOUND)
    message(FATAL_ERROR "SEFLEX_MPI=ON needs PETSc and SLEPc (pkg-config PETSc, SLEPc) and MPI: "
                        "install petsc-dev slepc-dev mpi-default-dev mpi-default-bin (scripts/install-deps.sh)")
  endif()
  find_program(SEFLEX_MPIEXEC NAMES mpirun mpiexec REQUIRED)
  add_library(seflex::petsc INTERFACE IMPORTED)
  target_link_libraries(seflex::petsc INTERFACE PkgConfig::SLEPC PkgConfig::PETSC MPI::MPI_C)
  message(STATUS "seflex: distributed backend ON (PETSc ${PETSC_VERSION}, SLEPc ${SLEPC_VERSION}, ${SEFLEX_MPIEXEC})")
else()
  message(STATUS "seflex: distributed backend OFF (SEFLEX_MPI; needs PETSc, SLEPc and MPI)")
endif()
