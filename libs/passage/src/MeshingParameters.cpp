#include "passageMesh/passage/MeshingParameters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/EtcFiles.hpp"
#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

namespace {

// Reads the keys of a meshDict into `p` (those present), lengths scaled by `chord`.
// Read into doubles, so that an integer far out of range (nT 4294967668) is clipped as
// written, not after a conversion to int has wrapped it.
void readEntries(const Dictionary& dict, double chord, std::array<double, MeshingParameters::size>& v) {
  const auto& table = MeshingParameters::table();
  for (int k = 0; k < MeshingParameters::size; ++k) {
    const MeshingParameterInfo& info = table[k];
    if (!dict.has(info.name)) continue;
    if (info.length)
      v[k] = dict.length(info.name, chord);
    else if (info.integer)
      v[k] = static_cast<double>(dict.integer(info.name));
    else
      v[k] = dict.scalar(info.name);
  }
}

std::vector<std::string> keys() {
  const auto& names = MeshingParameters::names();
  return {names.begin(), names.end()};
}

}  // namespace

MeshingParameters MeshingParameters::defaults(double chord) {
  static const Dictionary dict = [] {
    Dictionary d = Dictionary::read(findEtcFile("meshDictDefaults.xml"), "meshDict", keys());
    d.require(keys());
    return d;
  }();
  std::array<double, MeshingParameters::size> v = MeshingParameters{}.toArray();
  readEntries(dict, chord, v);
  return MeshingParameters::fromArray(v);
}

std::array<double, MeshingParameters::size> MeshingParameters::toArray() const {
  return {yIn, yOut, alphaCamber, betaIn, betaOut, static_cast<double>(nT), gammaLe, gammaTe, splitIn, splitOut};
}

MeshingParameters MeshingParameters::fromArray(const std::array<double, size>& v) {
  MeshingParameters p;
  p.yIn = v[0];
  p.yOut = v[1];
  p.alphaCamber = v[2];
  p.betaIn = v[3];
  p.betaOut = v[4];
  // Clamped to int's range first: beyond it lround's result is unspecified and the
  // conversion to int wraps (nT 4294967668 became 372).
  p.nT = static_cast<int>(std::lround(std::clamp(v[5], double(std::numeric_limits<int>::min()),
                                                 double(std::numeric_limits<int>::max()))));
  p.gammaLe = v[6];
  p.gammaTe = v[7];
  p.splitIn = v[8];
  p.splitOut = v[9];
  return p;
}

const std::array<MeshingParameterInfo, MeshingParameters::size>& MeshingParameters::table() {
  // name, lower, upper, length, integer (method.md section 1)
  static const std::array<MeshingParameterInfo, size> rows{{
      {"yIn", -0.5, 0.5, true, false},
      {"yOut", -0.5, 0.5, true, false},
      {"alphaCamber", 0.0, 1.0, false, false},
      {"betaIn", 0.1, 0.9, false, false},
      {"betaOut", 0.1, 0.9, false, false},
      {"nT", 100.0, 1000.0, false, true},
      {"gammaLE", 0.0, 5.0, false, false},
      {"gammaTE", 0.0, 5.0, false, false},
      {"splitIn", -0.5, 0.5, false, false},
      {"splitOut", -0.5, 0.5, false, false},
  }};
  return rows;
}

const std::array<std::string, MeshingParameters::size>& MeshingParameters::names() {
  static const std::array<std::string, size> n = [] {
    std::array<std::string, size> list;
    for (int k = 0; k < size; ++k) list[k] = table()[k].name;
    return list;
  }();
  return n;
}

namespace {

// One end of the range box (&MeshingParameterInfo::lower or ::upper), lengths in metres.
std::array<double, MeshingParameters::size> rangeEnd(double chord, double MeshingParameterInfo::*end) {
  std::array<double, MeshingParameters::size> v;
  for (int k = 0; k < MeshingParameters::size; ++k) {
    const MeshingParameterInfo& info = MeshingParameters::table()[k];
    v[k] = info.*end * (info.length ? chord : 1.0);
  }
  return v;
}

}  // namespace

std::array<double, MeshingParameters::size> MeshingParameters::lowerBounds(double chord) {
  return rangeEnd(chord, &MeshingParameterInfo::lower);
}

std::array<double, MeshingParameters::size> MeshingParameters::upperBounds(double chord) {
  return rangeEnd(chord, &MeshingParameterInfo::upper);
}

namespace {

std::array<double, MeshingParameters::size> clipArrayToRange(std::array<double, MeshingParameters::size> v,
                                                             double chord, std::vector<std::string>* warnings,
                                                             const std::string& source) {
  const auto lo = MeshingParameters::lowerBounds(chord), hi = MeshingParameters::upperBounds(chord);
  for (int k = 0; k < MeshingParameters::size; ++k) {
    const double clipped = std::clamp(v[k], lo[k], hi[k]);
    if (clipped != v[k] && warnings)
      warnings->push_back(source + ": <" + MeshingParameters::names()[k] + "> " +
                          formatExact(v[k]) + " is outside [" + formatShortest(lo[k]) + ", " + formatShortest(hi[k]) +
                          "], clipped to " + formatExact(clipped));
    v[k] = clipped;
  }
  return v;
}

}  // namespace

MeshingParameters readMeshDict(const std::filesystem::path& file, double chord,
                               std::vector<std::string>* warnings) {
  const MeshingParameters defaults = MeshingParameters::defaults(chord);
  if (!std::filesystem::exists(file)) return defaults;
  std::array<double, MeshingParameters::size> v = defaults.toArray();
  readEntries(Dictionary::read(file, "meshDict", keys()), chord, v);
  return MeshingParameters::fromArray(clipArrayToRange(v, chord, warnings, file.string()));
}

std::string meshDictXml(const MeshingParameters& p) {
  Dictionary dict("meshDict");
  dict.setComment("passageMesh meshing parameters; yIn, yOut in metres. See docs/case-format.md.");
  const auto v = p.toArray();
  for (int k = 0; k < MeshingParameters::size; ++k) {
    const MeshingParameterInfo& info = MeshingParameters::table()[k];
    if (info.integer)
      dict.set(info.name, std::to_string(std::lround(v[k])));
    else
      dict.set(info.name, v[k]);
  }
  return dict.toXml();
}

void writeMeshDict(const std::filesystem::path& file, const MeshingParameters& p) {
  writeFileAtomically(file, meshDictXml(p));
}

}  // namespace passageMesh
