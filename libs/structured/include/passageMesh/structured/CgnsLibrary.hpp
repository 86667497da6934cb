#pragma once
// The CGNS library's process-wide settings, shared by every reader and writer of CGNS files
// (libs/structured, libs/meshExport).

namespace passageMesh {

// Call before the first call into the CGNS library (cg_open, cg_is_cgns: each starts HDF5,
// after which the setting can no longer change). Turns off HDF5's exit handler, which closes the files still
// open when the process ends: a write that fails (disk full, file size limit) leaves HDF5 a
// file that cg_close cannot close, and the handler then crashed the tool after its one-line
// error (SIGSEGV in H5F__close_cb). Without it the operating system drops that file at
// exit and the tool ends with its own error code; files closed by cg_close, as every
// successful read and write closes them, are unaffected. Only the first call does anything.
void prepareCgnsLibrary();

}  // namespace passageMesh
