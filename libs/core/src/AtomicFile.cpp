#include "passageMesh/core/AtomicFile.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace passageMesh {

namespace {

std::filesystem::path temporaryFor(const std::filesystem::path& file) {
  return file.string() + ".tmp" + std::to_string(static_cast<long>(::getpid()));
}

void writeTemporary(const std::filesystem::path& file, const std::string& content) {
  namespace fs = std::filesystem;
  std::error_code ignored;
  if (file.has_parent_path()) fs::create_directories(file.parent_path(), ignored);
  const fs::path temporary = temporaryFor(file);
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  out << content;
  out.close();  // flushes: a deferred write error shows here
  if (!out) {
    fs::remove(temporary, ignored);
    throw std::runtime_error(file.string() + ": cannot write file");
  }
}

}  // namespace

void writeFilesAtomically(
    const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
  namespace fs = std::filesystem;
  std::error_code ignored;
  // A rename fails when its target is a directory (or another non-file): refuse before
  // anything is written. The temporaries sit beside their targets, so the renames cannot
  // fail for crossing file systems, and a directory that takes the temporaries takes the
  // renames: after this check and the writes, the renames go through together.
  for (const auto& [file, content] : files)
    if (fs::exists(file) && !fs::is_regular_file(file))
      throw std::runtime_error(file.string() + ": cannot replace, it is not a regular file");
  std::size_t written = 0;
  try {
    for (; written < files.size(); ++written) writeTemporary(files[written].first, files[written].second);
  } catch (...) {
    for (std::size_t k = 0; k < written; ++k) fs::remove(temporaryFor(files[k].first), ignored);
    throw;
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    std::error_code ec;
    fs::rename(temporaryFor(files[k].first), files[k].first, ec);
    if (ec) {
      const std::string why = ec.message();
      for (std::size_t m = k; m < files.size(); ++m) fs::remove(temporaryFor(files[m].first), ignored);
      throw std::runtime_error(files[k].first.string() + ": cannot replace file (" + why + ")");
    }
  }
}

void writeFileAtomically(const std::filesystem::path& file, const std::string& content) {
  writeFilesAtomically({{file, content}});
}

std::string formatExact(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace passageMesh
