#pragma once
// Scratch files for tests, under the system temporary directory.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
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

// A LibTorch file (a ZIP archive) with one byte of its first tensor's data changed and its
// structure intact: LibTorch's reader loads it, ZIP's CRC-32 tells (ZipChecksums.hpp).
inline void flipATensorByte(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  in.close();
  const std::size_t name = bytes.find("/data/0");  // the first tensor's local header name
  const std::size_t header = bytes.rfind("PK\x03\x04", name);
  if (name == std::string::npos || header == std::string::npos) throw std::runtime_error(file.string() + ": no tensor");
  const auto field = [&](std::size_t at) {
    return static_cast<std::size_t>(static_cast<unsigned char>(bytes[at])) |
           static_cast<std::size_t>(static_cast<unsigned char>(bytes[at + 1])) << 8;
  };
  bytes.at(header + 30 + field(header + 26) + field(header + 28) + 2) ^= 0x40;  // a float's byte
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace passageMesh::testData
