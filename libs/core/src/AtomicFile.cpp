#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/NumberFormat.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace passageMesh {

namespace {

std::filesystem::path temporaryFor(const std::filesystem::path& file) {
  return file.string() + ".tmp" + std::to_string(static_cast<long>(::getpid()));
}

void writeTemporary(const std::filesystem::path& file, const std::string& content,
                    const std::filesystem::path& temporary) {
  errno = 0;
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  out << content;
  out.close();  // flushes: a deferred write error shows here
  if (!out) throw std::runtime_error(file.string() + ": cannot write file (" + fileErrorReason("write error") + ")");
}

}  // namespace

void writeFilesAtomically(const std::vector<FileWriter>& files) {
  namespace fs = std::filesystem;
  std::error_code ignored;
  // A rename fails when its target is a directory (or another non-file): refuse before
  // anything is written. The temporaries sit beside their targets, so the renames cannot
  // fail for crossing file systems, and a directory that takes the temporaries takes the
  // renames: after this check and the writes, the renames go through together.
  for (const FileWriter& f : files)
    if (fs::exists(f.file) && !fs::is_regular_file(f.file))
      throw std::runtime_error(f.file.string() + ": cannot replace, it is not a regular file");
  std::size_t written = 0;
  try {
    for (; written < files.size(); ++written) {
      const fs::path& file = files[written].file;
      if (file.has_parent_path()) fs::create_directories(file.parent_path(), ignored);
      files[written].write(temporaryFor(file));
    }
  } catch (...) {
    // The one that failed may have left part of its temporary.
    for (std::size_t k = 0; k <= written && k < files.size(); ++k) fs::remove(temporaryFor(files[k].file), ignored);
    throw;
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    std::error_code ec;
    fs::rename(temporaryFor(files[k].file), files[k].file, ec);
    if (ec) {
      const std::string why = ec.message();
      for (std::size_t m = k; m < files.size(); ++m) fs::remove(temporaryFor(files[m].file), ignored);
      throw std::runtime_error(files[k].file.string() + ": cannot replace file (" + why + ")");
    }
  }
}

FileWriter fileWithContent(std::filesystem::path file, std::string content) {
  FileWriter writer{std::move(file), {}};
  writer.write = [file = writer.file, content = std::move(content)](const std::filesystem::path& temporary) {
    writeTemporary(file, content, temporary);
  };
  return writer;
}

void writeFilesAtomically(
    const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
  std::vector<FileWriter> writers;
  for (const auto& [file, content] : files) writers.push_back(fileWithContent(file, content));
  writeFilesAtomically(writers);
}

void writeFileAtomically(const std::filesystem::path& file, const std::string& content) {
  writeFilesAtomically({{file, content}});
}

std::string fileErrorReason(const std::string& fallback) {
  return errno != 0 ? std::strerror(errno) : fallback;
}

}  // namespace passageMesh
