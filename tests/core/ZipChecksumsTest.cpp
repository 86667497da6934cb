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
// LibTorch writes them (flag bit 3). With `zip64`, the ZIP64 layout: the end record's
// count and directory offset full (0xffff, 0xffffffff) and taken from the ZIP64 end
// record, and the member's header offset 0xffffffff in the directory, its value in the
// entry's ZIP64 extra field. `extra` replaces that extra field when given.
std::string oneMemberZip(bool zip64 = false, const std::string* extra = nullptr) {
  const std::string name = "a/data", data = "hello";
  const std::uint32_t crc = 0x3610a686;
  std::string zip = littleEndian(0x04034b50, 4) + littleEndian(20, 2) + littleEndian(8, 2) + littleEndian(0, 2) +
                    littleEndian(0, 4) + littleEndian(0, 4) + littleEndian(0, 4) + littleEndian(0, 4) +
                    littleEndian(name.size(), 2) + littleEndian(0, 2) + name + data +
                    littleEndian(0x08074b50, 4) + littleEndian(crc, 4) + littleEndian(data.size(), 4) +
                    littleEndian(data.size(), 4);
  const std::string zip64Extra = littleEndian(0x0001, 2) + littleEndian(8, 2) + littleEndian(0, 8);
  const std::string entryExtra = extra ? *extra : zip64 ? zip64Extra : "";
  const std::size_t directory = zip.size();
  zip += littleEndian(0x02014b50, 4) + littleEndian(45, 2) + littleEndian(45, 2) + littleEndian(8, 2) +
         littleEndian(0, 2) + littleEndian(0, 4) + littleEndian(crc, 4) + littleEndian(data.size(), 4) +
         littleEndian(data.size(), 4) + littleEndian(name.size(), 2) + littleEndian(entryExtra.size(), 2) +
         littleEndian(0, 2) + littleEndian(0, 2) + littleEndian(0, 2) + littleEndian(0, 4) +
         littleEndian(zip64 ? 0xffffffff : 0, 4) + name + entryExtra;
  const std::size_t directorySize = zip.size() - directory;
  if (zip64) {
    const std::size_t record = zip.size();
    zip += littleEndian(0x06064b50, 4) + littleEndian(44, 8) + littleEndian(45, 2) + littleEndian(45, 2) +
           littleEndian(0, 4) + littleEndian(0, 4) + littleEndian(1, 8) + littleEndian(1, 8) +
           littleEndian(directorySize, 8) + littleEndian(directory, 8);
    zip += littleEndian(0x07064b50, 4) + littleEndian(0, 4) + littleEndian(record, 8) + littleEndian(1, 4);
  }
  zip += littleEndian(0x06054b50, 4) + littleEndian(0, 2) + littleEndian(0, 2) + littleEndian(zip64 ? 0xffff : 1, 2) +
         littleEndian(zip64 ? 0xffff : 1, 2) + littleEndian(zip64 ? 0xffffffff : directorySize, 4) +
         littleEndian(zip64 ? 0xffffffff : directory, 4) + littleEndian(0, 2);
  return zip;
}

std::filesystem::path written(const std::string& name, const std::string& content) {
  return testData::writeTempFile("zipChecksums", name, content);
}

}  // namespace

TEST(ZipChecksums, AnIntactArchivePassesAndAChangedByteInAMemberIsFound) {
  const std::string zip = oneMemberZip();
  EXPECT_EQ(zipChecksumProblem(written("intact.zip", zip)), "");
  EXPECT_EQ(zipChecksumProblem(written("intact64.zip", oneMemberZip(true))), "");
  std::string changed = zip;
  changed[30 + 6 + 1] ^= 0x01;  // the "e" of "hello": local header (30) + name (6) + 1
  EXPECT_EQ(zipChecksumProblem(written("changed.zip", changed)),
            "member 'a/data' does not match its checksum (the file is corrupt)");
  std::string changed64 = oneMemberZip(true);
  changed64[30 + 6 + 1] ^= 0x01;
  EXPECT_EQ(zipChecksumProblem(written("changed64.zip", changed64)),
            "member 'a/data' does not match its checksum (the file is corrupt)");
}

TEST(ZipChecksums, ADamagedOrForeignFileIsDescribed) {
  const std::string zip = oneMemberZip();
  EXPECT_NE(zipChecksumProblem(written("short.zip", zip.substr(0, 20))).find("not a ZIP archive"), std::string::npos);
  EXPECT_NE(zipChecksumProblem(written("text.zip", "not a zip at all, just some words")).find("not a ZIP archive"),
            std::string::npos);
  std::string moved = zip;  // the directory's pointer to the member's header is off
  moved[zip.size() - 22 - 6 - 4] = 3;
  EXPECT_NE(zipChecksumProblem(written("moved.zip", moved)).find("member 'a/data' is missing"), std::string::npos);
  EXPECT_EQ(zipChecksumProblem(testData::tempFolder("zipChecksums") / "none.zip"), "cannot be read (not a file)");
  EXPECT_EQ(zipChecksumProblem(testData::tempFolder("zipChecksums")), "cannot be read (not a file)");  // a directory
  // Extra fields whose lengths run past their room, or a ZIP64 field with no value where the
  // directory says 0xffffffff: damaged, and nothing read beyond the file.
  const std::string tooLong = littleEndian(0x0001, 2) + littleEndian(200, 2) + littleEndian(0, 8);
  EXPECT_EQ(zipChecksumProblem(written("tooLong.zip", oneMemberZip(true, &tooLong))), "its central directory is damaged");
  const std::string empty64 = littleEndian(0x0001, 2) + littleEndian(0, 2);
  EXPECT_EQ(zipChecksumProblem(written("empty64.zip", oneMemberZip(true, &empty64))), "its central directory is damaged");
}
