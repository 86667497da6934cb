#include "passageMesh/structured/CgnsLibrary.hpp"

#include <cgnslib.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <utility>

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

CgnsOutputFile::CgnsOutputFile(const std::filesystem::path& path, std::string label)
    : label_(std::move(label)) {
  prepareCgnsLibrary();
  const int status = cg_open(path.c_str(), CG_MODE_WRITE, &fn_);
  if (status == CG_OK) return;
  // A failed open may still have taken a file index, and no destructor runs after a
  // constructor throws: the message is read before the close can replace it.
  const std::runtime_error error = failure("open");
  if (fn_ >= 0) cg_close(fn_);
  fn_ = -1;
  throw error;
}

CgnsOutputFile::~CgnsOutputFile() {
  if (fn_ >= 0) cg_close(fn_);
}

void CgnsOutputFile::check(int status, const std::string& what) const {
  if (status != CG_OK) throw failure(what);
}

std::runtime_error CgnsOutputFile::failure(const std::string& what) const {
  return std::runtime_error(label_ + ": CGNS " + what + " failed: " + cg_get_error());
}

void CgnsOutputFile::close() {
  const int f = fn_;
  fn_ = -1;
  check(cg_close(f), "close");
}

}  // namespace passageMesh
