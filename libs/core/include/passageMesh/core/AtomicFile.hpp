#pragma once
// Writing results so that a reader never sees a half-written file: the content goes to a
// temporary file beside the target, which is then renamed over it (atomic on POSIX).
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace passageMesh {

// Writes `content` to `file`, creating its parent directory. Throws std::runtime_error
// naming the file when it cannot be written; the target is then left as it was.
void writeFileAtomically(const std::filesystem::path& file, const std::string& content);

// Writes several files as one step: every content goes to its temporary file first, and
// only when all of them are written are they renamed over their targets, so a failure
// while writing leaves every target as it was.
void writeFilesAtomically(
    const std::vector<std::pair<std::filesystem::path, std::string>>& files);

// A file that a library writes itself (CGNS through its HDF5 layer), as one of the files
// of writeFilesAtomically: `write` writes the whole file to the path it is given (a
// temporary beside `file`) and throws when it cannot, naming `file`.
struct FileWriter {
  std::filesystem::path file;
  std::function<void(const std::filesystem::path& temporary)> write;
};

// The same for files written by FileWriters: all written, then all renamed, or none.
void writeFilesAtomically(const std::vector<FileWriter>& files);

// The FileWriter that writes `content` to `file`.
FileWriter fileWithContent(std::filesystem::path file, std::string content);

// Why the file operation just made failed, for a message: strerror(errno), or `fallback`
// where the operation set no errno. Clear errno (errno = 0) before the operation.
std::string fileErrorReason(const std::string& fallback);

}  // namespace passageMesh
