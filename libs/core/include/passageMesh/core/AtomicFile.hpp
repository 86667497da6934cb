#pragma once
// Writing results so that a reader never sees a half-written file: the content goes to a
// temporary file beside the target, which is then renamed over it (atomic on POSIX).
#include <filesystem>
#include <string>

namespace passageMesh {

// Writes `content` to `file`, creating its parent directory. Throws std::runtime_error
// naming the file when it cannot be written; the target is then left as it was.
void writeFileAtomically(const std::filesystem::path& file, const std::string& content);

// Formats a double with 17 significant digits, enough to read back the same value.
std::string formatExact(double value);

}  // namespace passageMesh
