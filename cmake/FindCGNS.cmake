# FindCGNS: Debian's libcgns-dev ships neither a CMake config nor a pkg-config file.
# Defines CGNS_FOUND, CGNS_INCLUDE_DIR, CGNS_LIBRARY and the imported target CGNS::CGNS.
find_path(CGNS_INCLUDE_DIR cgnslib.h PATH_SUFFIXES cgns)
find_library(CGNS_LIBRARY NAMES cgns)
# HDF5, which libcgns links, for H5dont_atexit (libs/structured/src/CgnsLibrary.cpp); the
# runtime library is enough (no libhdf5-dev): its unversioned name, else the installed soname.
file(GLOB CGNS_HDF5_CANDIDATES /usr/lib/*/libhdf5_serial.so.* /usr/lib/*/libhdf5.so.*)
find_library(CGNS_HDF5_LIBRARY NAMES hdf5_serial hdf5)
if(NOT CGNS_HDF5_LIBRARY AND CGNS_HDF5_CANDIDATES)
  list(SORT CGNS_HDF5_CANDIDATES)
  list(GET CGNS_HDF5_CANDIDATES 0 CGNS_HDF5_FIRST)
  set(CGNS_HDF5_LIBRARY "${CGNS_HDF5_FIRST}" CACHE FILEPATH "HDF5 library" FORCE)
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CGNS REQUIRED_VARS CGNS_LIBRARY CGNS_INCLUDE_DIR CGNS_HDF5_LIBRARY)
if(CGNS_FOUND AND NOT TARGET CGNS::CGNS)
  add_library(CGNS::CGNS UNKNOWN IMPORTED)
  set_target_properties(CGNS::CGNS PROPERTIES
    IMPORTED_LOCATION "${CGNS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CGNS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CGNS_HDF5_LIBRARY}")
endif()
mark_as_advanced(CGNS_INCLUDE_DIR CGNS_LIBRARY CGNS_HDF5_LIBRARY)
