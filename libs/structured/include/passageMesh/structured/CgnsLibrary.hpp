#pragma once
// The CGNS library's process-wide settings, shared by every reader and writer of CGNS files
// (libs/structured, libs/meshExport), and the output file every CGNS writer writes through.

#include <filesystem>
#include <stdexcept>
#include <string>

namespace passageMesh {

// Call before the first call into the CGNS library (cg_open, cg_is_cgns: each starts HDF5,
// after which the setting can no longer change). Turns off HDF5's exit handler, which closes the files still
// open when the process ends: a write that fails (disk full, file size limit) leaves HDF5 a
// file that cg_close cannot close, and the handler then crashed the tool after its one-line
// error (SIGSEGV in H5F__close_cb). Without it the operating system drops that file at
// exit and the tool ends with its own error code; files closed by cg_close, as every
// successful read and write closes them, are unaffected. Only the first call does anything.
void prepareCgnsLibrary();

// A CGNS file open for writing, closed on every path out, a failed cg_open included (the
// constructor closes a file index the failed open took; the writers write a temporary
// that their callers remove). Every failing call throws
// std::runtime_error "<label>: CGNS <what> failed: <CGNS's message>", the label naming the
// file the user knows (the target, when the path written is its staged temporary).
class CgnsOutputFile {
 public:
  CgnsOutputFile(const std::filesystem::path& path, std::string label);
  ~CgnsOutputFile();
  CgnsOutputFile(const CgnsOutputFile&) = delete;
  CgnsOutputFile& operator=(const CgnsOutputFile&) = delete;

  // Throws as above when `status` (a CGNS return code) is not CG_OK.
  void check(int status, const std::string& what) const;
  // Closes the file, checking that the close succeeded (HDF5 writes at the close).
  void close();
  int fn() const { return fn_; }  // the CGNS file index

 private:
  // "<label>: CGNS <what> failed: <CGNS's message>", CGNS's message read now.
  std::runtime_error failure(const std::string& what) const;
  std::string label_;
  int fn_ = -1;
};

}  // namespace passageMesh
