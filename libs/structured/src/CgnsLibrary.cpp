#include "passageMesh/structured/CgnsLibrary.hpp"

#include <dlfcn.h>

namespace passageMesh {

void prepareCgnsLibrary() {
  // H5dont_atexit (HDF5's public C API, H5public.h) is looked up in the process: HDF5 is
  // libcgns's own dependency and Debian's libcgns-dev brings neither its headers nor a
  // name to link it by. It fails (harmlessly) once HDF5 has started, so only the first
  // call counts.
  static const bool prepared = [] {
    using DontAtExit = int (*)();
    if (const auto dontAtExit = reinterpret_cast<DontAtExit>(::dlsym(RTLD_DEFAULT, "H5dont_atexit")))
      dontAtExit();
    return true;
  }();
  static_cast<void>(prepared);
}

}  // namespace passageMesh
