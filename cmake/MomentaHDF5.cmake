# HDF5 for the sweeps' trajectory files, found once for every target that includes its headers
# (the sweep library, its tests). Sets MOMENTA_HAVE_HDF5 and MOMENTA_HDF5_PARALLEL and defines
# momenta_link_hdf5(TARGET).
#
# Debian installs two flavours side by side: the serial one (libhdf5-dev, h5cc) and Open MPI's
# parallel one (libhdf5-openmpi-dev, h5pcc, pulled in by libsundials-dev through PETSc), and its
# alternatives name the parallel one first. momenta writes each HDF5 file from one process (rank 0
# of an MPI sweep gathers the runs), so it asks for the serial flavour: its headers stand alone,
# and nothing that includes them needs MPI. Where only the parallel flavour is found (or it is
# chosen: -DHDF5_C_COMPILER_EXECUTABLE=/usr/bin/h5pcc, or a cache that found it first), its
# hdf5.h includes mpi.h, so MPI's C target goes wherever HDF5's does, the installed package
# finds both again, and a build without MPI leaves HDF5 out with a message.
include_guard(GLOBAL)

enable_language(C)  # FindHDF5 and FindMPI probe with a C compiler
set(HDF5_PREFER_PARALLEL OFF)
find_package(HDF5 COMPONENTS C QUIET)
set(MOMENTA_HAVE_HDF5 ${HDF5_FOUND})
set(MOMENTA_HDF5_PARALLEL OFF)
if(HDF5_FOUND AND HDF5_IS_PARALLEL)
  find_package(MPI COMPONENTS C QUIET)
  if(MPI_C_FOUND)
    set(MOMENTA_HDF5_PARALLEL ON)
  else()
    message(STATUS "momenta: the HDF5 found (${HDF5_C_COMPILER_EXECUTABLE}) is MPI's parallel "
                   "flavour and MPI's C library is not found: sweeps write no HDF5 files "
                   "(install libhdf5-dev, the serial flavour, or libopenmpi-dev)")
    set(MOMENTA_HAVE_HDF5 OFF)
  endif()
endif()
set(flavour none)
if(MOMENTA_HAVE_HDF5)
  set(flavour serial)
  if(MOMENTA_HDF5_PARALLEL)
    set(flavour "parallel, with MPI")
  endif()
  message(STATUS "momenta: HDF5 ${HDF5_VERSION} (${flavour}) from ${HDF5_C_INCLUDE_DIRS}")
endif()
set(MOMENTA_HDF5_FLAVOUR "${flavour}" CACHE INTERNAL "The HDF5 the sweep library uses (cmake/MomentaHDF5.cmake)")

# Links HDF5 (and MPI's C target where HDF5 is the parallel flavour) into TARGET, privately, and
# defines DEFINITION there; nothing without HDF5.
function(momenta_link_hdf5 target definition)
  if(NOT MOMENTA_HAVE_HDF5)
    return()
  endif()
  target_link_libraries(${target} PRIVATE HDF5::HDF5)
  target_compile_definitions(${target} PRIVATE ${definition})
  if(MOMENTA_HDF5_PARALLEL)
    target_link_libraries(${target} PRIVATE MPI::MPI_C)
    # The C interface only: Open MPI's mpi.h otherwise pulls in its removed C++ bindings.
    target_compile_definitions(${target} PRIVATE OMPI_SKIP_MPICXX MPICH_SKIP_MPICXX)
  endif()
endfunction()
