#pragma once
// Scratch files for tests, under the system temporary directory.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace passageMesh::testData {

// A folder of this test process under the system temporary directory (the process id
// keeps concurrent test runs apart).
inline std::filesystem::path tempFolder(const std::string& folder) {
  return std::filesystem::temp_directory_path() /
         ("passageMeshTests." + std::to_string(static_cast<long>(::getpid()))) / folder;
}

// Writes `content` to <tempFolder(folder)>/<name> and returns that path.
inline std::filesystem::path writeTempFile(const std::string& folder, const std::string& name,
                                           const std::string& content) {
  const auto dir = tempFolder(folder);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << content;
  return dir / name;
}

}  // namespace passageMesh::testData
