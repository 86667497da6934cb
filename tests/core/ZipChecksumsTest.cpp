#include "passageMesh/core/ZipChecksums.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "../TestFiles.hpp"

using namespace passageMesh;

namespace {

std::string littleEndian(std::uint64_t value, int bytes) {
  std::string s;
  for (int k = 0; k < bytes; ++k) s += static_cast<char>((value >> (8 * k)) & 0xff);
  return s;
}

// A ZIP archive of one stored member "a/data" holding "hello" (CRC-32 0x3610a686), written
// field by field as APPNOTE.TXT lays it out, with the sizes in a data descriptor as
// LibTorch writes them (flag bit 3).
std::string oneMemberZip() {
  const std::string name = "a/data", data = "hello";
  const std::uint32_t crc = 0x3610a686;
  std::string zip = littleEndian(0x04034b50, 4) + littleEndian(20, 2) + littleEndian(8, 2) + littleEndian(0, 2) +
                    littleEndian(0, 4) + littleEndian(0, 4) + littleEndian(0, 4) + littleEndian(0, 4) +
                    littleEndian(name.size(), 2) + littleEndian(0, 2) + name + data +
                    littleEndian(0x08074b50, 4) + littleEndian(crc, 4) + littleEndian(data.size(), 4) +
                    littleEndian(data.size(), 4);
  const std::size_t directory = zip.size();
  zip += littleEndian(0x02014b50, 4) + littleEndian(20, 2) + littleEndian(20, 2) + littleEndian(8, 2) +
         littleEndian(0, 2) + littleEndian(0, 4) + littleEndian(crc, 4) + littleEndian(data.size(), 4) +
         littleEndian(data.size(), 4) + littleEndian(name.size(), 2) + littleEndian(0, 2) + littleEndian(0, 2) +
         littleEndian(0, 2) + littleEndian(0, 2) + littleEndian(0, 4) + littleEndian(0, 4) + name;
  const std::size_t directorySize = zip.size() - directory;
  zip += littleEndian(0x06054b50, 4) + littleEndian(0, 2) + littleEndian(0, 2) + littleEndian(1, 2) +
         littleEndian(1, 2) + littleEndian(directorySize, 4) + littleEndian(directory, 4) + littleEndian(0, 2);
  return zip;
}

std::filesystem::path written(const std::string& name, const std::string& content) {
  return testData::writeTempFile("zipChecksums", name, content);
}

}  // namespace

TEST(ZipChecksums, AnIntactArchivePassesAndAChangedByteInAMemberIsFound) {
  const std::string zip = oneMemberZip();
  EXPECT_EQ(zipChecksumProblem(written("intact.zip", zip)), "");
  std::string changed = zip;
  changed[30 + 6 + 1] ^= 0x01;  // the "e" of "hello": local header (30) + name (6) + 1
  EXPECT_EQ(zipChecksumProblem(written("changed.zip", changed)), "member 'a/data' does not match its checksum");
}

TEST(ZipChecksums, ADamagedOrForeignFileIsDescribed) {
  const std::string zip = oneMemberZip();
  EXPECT_NE(zipChecksumProblem(written("short.zip", zip.substr(0, 20))).find("not a ZIP archive"), std::string::npos);
  EXPECT_NE(zipChecksumProblem(written("text.zip", "not a zip at all, just some words")).find("not a ZIP archive"),
            std::string::npos);
  std::string moved = zip;  // the directory's pointer to the member's header is off
  moved[zip.size() - 22 - 6 - 4] = 3;
  EXPECT_NE(zipChecksumProblem(written("moved.zip", moved)).find("member 'a/data' is missing"), std::string::npos);
  EXPECT_EQ(zipChecksumProblem(testData::tempFolder("zipChecksums") / "none.zip"), "cannot be read");
}
