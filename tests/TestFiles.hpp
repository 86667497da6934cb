#pragma once
// Scratch files for tests, under the system temporary directory.
#include <filesystem>
#include <fstream>
#include <string>

namespace passageMesh::testData {

// Writes `content` to <tmp>/<folder>/<name> and returns that path.
inline std::filesystem::path writeTempFile(const std::string& folder, const std::string& name,
                                           const std::string& content) {
  const auto dir = std::filesystem::temp_directory_path() / folder;
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << content;
  return dir / name;
}

}  // namespace passageMesh::testData
