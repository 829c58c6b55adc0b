# FindCQRlib: H. J. Bernstein's CQRlib (Debian: libcqrlib-dev). It ships no pkg-config file and no
# CMake config, so the header and the library are looked up directly.
#
# Result variables:  CQRlib_FOUND, CQRlib_INCLUDE_DIR, CQRlib_LIBRARY
# Imported target:   CQRlib::CQRlib
#
# The header carries no version macro; Debian 12 ships 1.1.4 (the adapter's adapter.json says so).
find_path(CQRlib_INCLUDE_DIR NAMES cqrlib.h)
find_library(CQRlib_LIBRARY NAMES CQRlib)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CQRlib REQUIRED_VARS CQRlib_LIBRARY CQRlib_INCLUDE_DIR)
mark_as_advanced(CQRlib_INCLUDE_DIR CQRlib_LIBRARY)

if(CQRlib_FOUND AND NOT TARGET CQRlib::CQRlib)
  add_library(CQRlib::CQRlib UNKNOWN IMPORTED)
  set_target_properties(CQRlib::CQRlib PROPERTIES
    IMPORTED_LOCATION "${CQRlib_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CQRlib_INCLUDE_DIR}")
  # The library calls sqrt, atan2, ... from libm.
  find_library(CQRlib_M_LIBRARY NAMES m)
  mark_as_advanced(CQRlib_M_LIBRARY)
  if(CQRlib_M_LIBRARY)
    set_property(TARGET CQRlib::CQRlib APPEND PROPERTY INTERFACE_LINK_LIBRARIES "${CQRlib_M_LIBRARY}")
  endif()
endif()
