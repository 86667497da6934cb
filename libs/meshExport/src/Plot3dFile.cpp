#include "passageMesh/meshExport/Plot3dFile.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

std::string plot3dAscii(const StructuredMesh& mesh, double thickness) {
  std::ostringstream out;
  out << mesh.blocks.size() << '\n';
  for (const auto& b : mesh.blocks) out << b.ni << ' ' << b.nj << " 2\n";
  for (const auto& b : mesh.blocks) {
    int column = 0;
    const auto put = [&](double v) { out << formatExact(v) << (++column % 5 == 0 ? '\n' : ' '); };
    for (int k = 0; k < 2; ++k)
      for (const double v : b.x) put(v);
    for (int k = 0; k < 2; ++k)
      for (const double v : b.y) put(v);
    for (int k = 0; k < 2; ++k)
      for (std::size_t n = 0; n < b.x.size(); ++n) put(k * thickness);
    if (column % 5 != 0) out << '\n';
  }
  return out.str();
}

namespace {

// Little-endian bytes of a value, whatever the host's byte order.
template <typename T>
void putLittleEndian(std::string& out, T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + sizeof(T));
  out.append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

// A Fortran sequential record: its length, the payload, its length again.
void putRecord(std::string& out, const std::string& payload) {
  putLittleEndian(out, static_cast<std::int32_t>(payload.size()));
  out += payload;
  putLittleEndian(out, static_cast<std::int32_t>(payload.size()));
}

}  // namespace

std::string plot3dBinary(const StructuredMesh& mesh, double thickness) {
  std::string out, record;
  putLittleEndian(record, static_cast<std::int32_t>(mesh.blocks.size()));
  putRecord(out, record);
  record.clear();
  for (const auto& b : mesh.blocks)
    for (const int n : {b.ni, b.nj, 2}) putLittleEndian(record, static_cast<std::int32_t>(n));
  putRecord(out, record);
  for (const auto& b : mesh.blocks) {
    record.clear();
    for (int k = 0; k < 2; ++k)
      for (const double v : b.x) putLittleEndian(record, v);
    for (int k = 0; k < 2; ++k)
      for (const double v : b.y) putLittleEndian(record, v);
    for (int k = 0; k < 2; ++k)
      for (std::size_t n = 0; n < b.x.size(); ++n) putLittleEndian(record, k * thickness);
    putRecord(out, record);
  }
  return out;
}

}  // namespace passageMesh
