# Finds every third-party library stella uses. Each comes from a Debian 12 package; when one is
# missing, configuration stops with the name of the package to install (tools/install-deps
# installs them all).

function(stella_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR "stella needs ${what}, which was not found.\n"
                        "Install the Debian package '${package}' (or run tools/install-deps).")
  endif()
endfunction()

find_package(Eigen3 3.4 QUIET NO_MODULE)
stella_require(Eigen3_FOUND "Eigen 3.4" libeigen3-dev)

find_package(fmt QUIET)
stella_require(fmt_FOUND "fmt" libfmt-dev)

find_package(CLI11 QUIET)
if(NOT CLI11_FOUND)
  find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp)
  if(CLI11_INCLUDE_DIR)
    add_library(CLI11::CLI11 INTERFACE IMPORTED)
    set_target_properties(CLI11::CLI11 PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${CLI11_INCLUDE_DIR}")
    set(CLI11_FOUND TRUE)
  endif()
endif()
stella_require(CLI11_FOUND "CLI11" libcli11-dev)

find_package(GTest QUIET)
stella_require(GTest_FOUND "GoogleTest" libgtest-dev)

find_package(HDF5 QUIET COMPONENTS C)
stella_require(HDF5_FOUND "HDF5" libhdf5-dev)

# Boost.Geometry's R-tree (header-only) indexes the contact master cells (solver/contact).
find_path(BOOST_GEOMETRY_INCLUDE_DIR boost/geometry/index/rtree.hpp)
if(BOOST_GEOMETRY_INCLUDE_DIR)
  add_library(Boost::geometry INTERFACE IMPORTED)
  set_target_properties(Boost::geometry PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${BOOST_GEOMETRY_INCLUDE_DIR}")
endif()
stella_require(BOOST_GEOMETRY_INCLUDE_DIR "Boost.Geometry" libboost-dev)

# zlib compresses the appended data of the VTU result files (IMPR_RESU FORMAT='VTU').
find_package(ZLIB QUIET)
stella_require(ZLIB_FOUND "zlib" zlib1g-dev)

find_path(MED_INCLUDE_DIR med.h PATH_SUFFIXES med)
find_library(MED_LIBRARY NAMES medC)
if(MED_INCLUDE_DIR AND MED_LIBRARY)
  add_library(MED::medC UNKNOWN IMPORTED)
  set_target_properties(MED::medC PROPERTIES IMPORTED_LOCATION "${MED_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${MED_INCLUDE_DIR};${HDF5_INCLUDE_DIRS}"
                        INTERFACE_LINK_LIBRARIES "${HDF5_C_LIBRARIES}")
  set(MED_FOUND TRUE)
endif()
stella_require(MED_FOUND "the MED library (libmedC)" libmedc-dev)

# MPI (issue 21): with STELLA_MPI=ON and OpenMPI plus the parallel MUMPS installed
# (mpi-default-dev, libmumps-dev), stella links the parallel MUMPS and MPI and runs under
# `mpirun -n N` or `P mpi_nbcpu N` (doc/parallel.md); otherwise the sequential MUMPS with its fake
# MPI. The two MUMPS libraries define the same symbols: one executable links one of them.
# Off by default: Debian's parallel MUMPS has no SCOTCH (RENUM='SCOTCH' refused, AUTO takes PORD:
# +30 % factorisation flops on 3D cubes) and a serial run would pay MPI's start-up (0.2 s), so a
# study on one process would pay for a feature it does not use. tools/test-all builds it beside.
option(STELLA_MPI "Link MPI and the parallel MUMPS: stella runs under mpirun (doc/parallel.md)" OFF)
if(STELLA_MPI AND STELLA_SANITIZE)
  message(FATAL_ERROR "STELLA_MPI with STELLA_SANITIZE: the leak checker reports OpenMPI's allocations at exit")
endif()
set(STELLA_HAVE_MPI FALSE)
find_path(MUMPS_INCLUDE_DIR dmumps_c.h)
if(STELLA_MPI)
  find_package(MPI QUIET COMPONENTS C)
  find_library(MUMPS_MPI_D_LIBRARY NAMES dmumps NAMES_PER_DIR)
  find_library(MUMPS_MPI_S_LIBRARY NAMES smumps NAMES_PER_DIR)
  find_library(MUMPS_MPI_COMMON_LIBRARY NAMES mumps_common NAMES_PER_DIR)
  find_program(STELLA_MPIEXEC NAMES mpirun mpiexec)
  if(MPI_C_FOUND AND MUMPS_MPI_D_LIBRARY AND MUMPS_MPI_S_LIBRARY AND MUMPS_MPI_COMMON_LIBRARY AND STELLA_MPIEXEC)
    set(STELLA_HAVE_MPI TRUE)
    set(MUMPS_D_LIBRARY ${MUMPS_MPI_D_LIBRARY})
    set(MUMPS_S_LIBRARY ${MUMPS_MPI_S_LIBRARY})
    set(MUMPS_COMMON_LIBRARY ${MUMPS_MPI_COMMON_LIBRARY})
    message(STATUS "MPI ${MPI_C_VERSION} and the parallel MUMPS: stella runs under ${STELLA_MPIEXEC}")
  else()
    message(STATUS "MPI, mpirun or the parallel MUMPS not found: stella is sequential "
                   "(install mpi-default-dev libmumps-dev)")
  endif()
endif()
if(NOT STELLA_HAVE_MPI)
  find_library(MUMPS_D_LIBRARY NAMES dmumps_seq dmumps)
  find_library(MUMPS_COMMON_LIBRARY NAMES mumps_common_seq mumps_common)
  # single precision: the LDLT_SP preconditioner of GCPC
  find_library(MUMPS_S_LIBRARY NAMES smumps_seq smumps)
  find_library(MUMPS_PORD_LIBRARY NAMES pord_seq pord)
  find_library(MUMPS_MPISEQ_LIBRARY NAMES mpiseq_seq mpiseq)
endif()
if(MUMPS_INCLUDE_DIR AND MUMPS_D_LIBRARY AND MUMPS_S_LIBRARY AND MUMPS_COMMON_LIBRARY)
  add_library(MUMPS::dmumps INTERFACE IMPORTED)
  set(_mumps_libs "${MUMPS_D_LIBRARY};${MUMPS_S_LIBRARY};${MUMPS_COMMON_LIBRARY}")
  if(STELLA_HAVE_MPI)
    list(APPEND _mumps_libs "$<LINK_ONLY:MPI::MPI_C>") # mpi.h only in solver/parallel/Mpi.cpp
  else()
    foreach(_lib MUMPS_PORD_LIBRARY MUMPS_MPISEQ_LIBRARY)
      if(${_lib})
        list(APPEND _mumps_libs "${${_lib}}")
      endif()
    endforeach()
  endif()
  set_target_properties(MUMPS::dmumps PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}"
                        INTERFACE_LINK_LIBRARIES "${_mumps_libs}")
  set(MUMPS_FOUND TRUE)
endif()
stella_require(MUMPS_FOUND "sequential MUMPS" libmumps-seq-dev)

find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(UMFPACK_LIBRARY umfpack)
find_library(SUITESPARSE_CONFIG_LIBRARY suitesparseconfig)
if(SUITESPARSE_INCLUDE_DIR AND CHOLMOD_LIBRARY AND UMFPACK_LIBRARY)
  add_library(SuiteSparse::solvers INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::solvers PROPERTIES
                        INTERFACE_INCLUDE_DIRECTORIES "${SUITESPARSE_INCLUDE_DIR}"
                        INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARY};${UMFPACK_LIBRARY};${SUITESPARSE_CONFIG_LIBRARY}")
  set(SUITESPARSE_FOUND TRUE)
endif()
stella_require(SUITESPARSE_FOUND "SuiteSparse (CHOLMOD, UMFPACK)" libsuitesparse-dev)

if(STELLA_BENCHMARKS)
  find_package(benchmark QUIET)
  stella_require(benchmark_FOUND "Google Benchmark" libbenchmark-dev)
endif()

# Python with matplotlib, h5py and meshio: Debian's interpreter, never a user's own one.
find_program(STELLA_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT STELLA_PYTHON)
  find_program(STELLA_PYTHON python3)
endif()
find_program(GMSH_PROGRAM gmsh)
stella_require(GMSH_PROGRAM "Gmsh" gmsh)

# PETSc (optional): SOLVEUR METHODE='PETSC' runs in the worker process `stella-petsc`
# (tools/petsc-worker), the only program linking PETSc, MPI and the parallel MUMPS; stella keeps
# the sequential MUMPS and no MPI. Without PETSc (or with -DSTELLA_PETSC=OFF) stella builds as
# before and refuses METHODE='PETSC' at the keyword, naming the package (petsc-dev).
option(STELLA_PETSC "Build the PETSc worker of SOLVEUR METHODE='PETSC' when PETSc is found" ON)
set(STELLA_HAVE_PETSC FALSE)
if(STELLA_PETSC)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc)
  endif()
  find_package(MPI QUIET COMPONENTS C)
  find_library(MUMPS_PARALLEL_S_LIBRARY NAMES smumps NAMES_PER_DIR)
  find_library(MUMPS_PARALLEL_COMMON_LIBRARY NAMES mumps_common NAMES_PER_DIR)
  if(PETSC_FOUND AND MPI_C_FOUND AND MUMPS_PARALLEL_S_LIBRARY AND MUMPS_PARALLEL_COMMON_LIBRARY)
    set(STELLA_HAVE_PETSC TRUE)
    message(STATUS "PETSc ${PETSC_VERSION}: SOLVEUR METHODE='PETSC' through bin/stella-petsc")
  else()
    message(STATUS "PETSc, MPI or the parallel MUMPS not found: METHODE='PETSC' refused (install petsc-dev)")
  endif()
endif()
