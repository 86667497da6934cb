#include "passageMesh/core/AtomicFile.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "passageMesh/core/StagedOutputs.hpp"

namespace passageMesh {

namespace {

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
  // Each is written to its temporary beside its target (same file system, so the renames
  // at the commit cannot fail for crossing file systems); a failure leaves every target as
  // it was, the temporaries removed.
  StagedOutputs staged;
  for (const FileWriter& f : files) staged.write(f);
  staged.commit();
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
