#include "passageMesh/structured/CgnsLibrary.hpp"

// HDF5's public C API (H5public.h; herr_t is int). Declared here because Debian's
// libcgns-dev does not bring HDF5's headers; the library itself is CGNS's own dependency.
extern "C" int H5dont_atexit(void);

namespace passageMesh {

void prepareCgnsLibrary() {
  // Fails (harmlessly) once HDF5 has started, so only the first call counts.
  static const bool prepared = (H5dont_atexit(), true);
  static_cast<void>(prepared);
}

}  // namespace passageMesh
