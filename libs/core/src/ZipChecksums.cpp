#include "passageMesh/core/ZipChecksums.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <utility>
#include <vector>

namespace passageMesh {

namespace {

// The ZIP layout (PKWARE's APPNOTE.TXT): little-endian fields at fixed offsets.
constexpr std::uint32_t localHeaderSignature = 0x04034b50, centralHeaderSignature = 0x02014b50,
                        endSignature = 0x06054b50, zip64EndSignature = 0x06064b50,
                        zip64LocatorSignature = 0x07064b50;
constexpr std::uint32_t spilled32 = 0xffffffff;  // the value is in the ZIP64 extra field
constexpr std::uint16_t spilled16 = 0xffff;

class Bytes {
 public:
  explicit Bytes(std::vector<unsigned char> data) : data_(std::move(data)) {}
  std::size_t size() const { return data_.size(); }
  bool has(std::uint64_t offset, std::uint64_t length) const {
    return offset <= data_.size() && length <= data_.size() - offset;
  }
  std::uint64_t read(std::uint64_t offset, int length) const {  // caller checked has()
    std::uint64_t value = 0;
    for (int k = length - 1; k >= 0; --k) value = (value << 8) | data_[static_cast<std::size_t>(offset) + k];
    return value;
  }
  const unsigned char* at(std::uint64_t offset) const { return data_.data() + offset; }

 private:
  std::vector<unsigned char> data_;
};

struct Directory {
  std::uint64_t entries = 0, offset = 0;
};

// The central directory's place, from the end record (ZIP64's where that one is full).
bool findDirectory(const Bytes& b, Directory& d) {
  if (b.size() < 22) return false;
  const std::uint64_t lowest = b.size() > 22 + 65535 ? b.size() - 22 - 65535 : 0;
  for (std::uint64_t end = b.size() - 22 + 1; end-- > lowest;) {
    if (b.read(end, 4) != endSignature) continue;
    d.entries = b.read(end + 10, 2);
    d.offset = b.read(end + 16, 4);
    if (d.entries != spilled16 && d.offset != spilled32) return true;
    if (end < 20 || b.read(end - 20, 4) != zip64LocatorSignature) return false;
    const std::uint64_t record = b.read(end - 20 + 8, 8);
    if (!b.has(record, 56) || b.read(record, 4) != zip64EndSignature) return false;
    d.entries = b.read(record + 32, 8);
    d.offset = b.read(record + 48, 8);
    return true;
  }
  return false;
}

}  // namespace

std::string zipChecksumProblem(const std::filesystem::path& file) {
  // (a directory opens, and sizes as anything: refused first)
  if (!std::filesystem::is_regular_file(file)) return "cannot be read (not a file)";
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  const std::streamoff fileSize = in.tellg();
  if (!in || fileSize < 0) return "cannot be read";
  std::vector<unsigned char> content(static_cast<std::size_t>(fileSize));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(content.data()), static_cast<std::streamsize>(content.size())))
    return "cannot be read";
  const Bytes b(std::move(content));
  Directory d;
  if (!findDirectory(b, d)) return "not a ZIP archive (no end of central directory)";
  std::uint64_t at = d.offset;
  for (std::uint64_t n = 0; n < d.entries; ++n) {
    if (!b.has(at, 46) || b.read(at, 4) != centralHeaderSignature) return "its central directory is damaged";
    const int method = static_cast<int>(b.read(at + 10, 2));
    const std::uint32_t crc = static_cast<std::uint32_t>(b.read(at + 16, 4));
    std::uint64_t size = b.read(at + 20, 4), local = b.read(at + 42, 4);
    const std::uint64_t uncompressed = b.read(at + 24, 4);
    const std::uint64_t nameLength = b.read(at + 28, 2), extraLength = b.read(at + 30, 2),
                        commentLength = b.read(at + 32, 2);
    if (!b.has(at + 46, nameLength + extraLength + commentLength)) return "its central directory is damaged";
    const std::string name(reinterpret_cast<const char*>(b.at(at + 46)), static_cast<std::size_t>(nameLength));
    // ZIP64: the 8-byte values of the fields that hold 0xffffffff, in this order. Every
    // length read from the file is checked against the extra field it lies in.
    const std::uint64_t extraEnd = at + 46 + nameLength + extraLength;
    for (std::uint64_t e = at + 46 + nameLength; e + 4 <= extraEnd;) {
      const std::uint64_t id = b.read(e, 2), length = b.read(e + 2, 2);
      if (e + 4 + length > extraEnd) return "its central directory is damaged";
      if (id == 0x0001) {
        std::uint64_t field = e + 4;
        const auto take = [&](std::uint64_t& value) {
          if (value != spilled32) return true;
          if (field + 8 > e + 4 + length) return false;
          value = b.read(field, 8);
          field += 8;
          return true;
        };
        std::uint64_t unused = uncompressed;
        if (!take(unused) || !take(size) || !take(local)) return "its central directory is damaged";
      }
      e += 4 + length;
    }
    if (method == 0) {
      if (!b.has(local, 30) || b.read(local, 4) != localHeaderSignature)
        return "member '" + name + "' is missing (no local header where the directory points)";
      const std::uint64_t data = local + 30 + b.read(local + 26, 2) + b.read(local + 28, 2);
      if (!b.has(data, size)) return "member '" + name + "' is cut short";
      uLong sum = crc32(0L, Z_NULL, 0);
      for (std::uint64_t done = 0; done < size;) {  // (crc32 takes at most 4 GiB a call)
        const std::uint64_t chunk = std::min<std::uint64_t>(size - done, 1u << 30);
        sum = crc32(sum, b.at(data + done), static_cast<uInt>(chunk));
        done += chunk;
      }
      if (static_cast<std::uint32_t>(sum) != crc)
        return "member '" + name + "' does not match its checksum (the file is corrupt)";
    }
    at += 46 + nameLength + extraLength + commentLength;
  }
  return "";
}

}  // namespace passageMesh
