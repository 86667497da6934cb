#include "passageMesh/passage/MeshingParameters.hpp"

#include <algorithm>
#include <cmath>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/EtcFiles.hpp"

namespace passageMesh {

namespace {

// Reads the keys of a meshDict into `p` (those present), lengths scaled by `chord`.
void readEntries(const Dictionary& dict, double chord, MeshingParameters& p) {
  const auto& names = MeshingParameters::names();
  auto v = p.toArray();
  for (int k = 0; k < MeshingParameters::size; ++k) {
    if (!dict.has(names[k])) continue;
    if (k <= 1)
      v[k] = dict.length(names[k], chord);
    else if (names[k] == "nT")
      v[k] = static_cast<double>(dict.integer(names[k]));
    else
      v[k] = dict.scalar(names[k]);
  }
  p = MeshingParameters::fromArray(v);
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
  MeshingParameters p;
  readEntries(dict, chord, p);
  return p;
}

std::array<double, MeshingParameters::size> MeshingParameters::toArray() const {
  return {yIn, yOut, alphaCamber, betaIn, betaOut, static_cast<double>(nT), gammaLe, gammaTe};
}

MeshingParameters MeshingParameters::fromArray(const std::array<double, size>& v) {
  MeshingParameters p;
  p.yIn = v[0];
  p.yOut = v[1];
  p.alphaCamber = v[2];
  p.betaIn = v[3];
  p.betaOut = v[4];
  p.nT = static_cast<int>(std::lround(v[5]));
  p.gammaLe = v[6];
  p.gammaTe = v[7];
  return p;
}

const std::array<std::string, MeshingParameters::size>& MeshingParameters::names() {
  static const std::array<std::string, size> n{"yIn",  "yOut", "alphaCamber", "betaIn",
                                               "betaOut", "nT", "gammaLE",     "gammaTE"};
  return n;
}

std::array<double, MeshingParameters::size> MeshingParameters::lowerBounds(double chord) {
  return {-0.5 * chord, -0.5 * chord, 0.0, 0.1, 0.1, 100.0, 0.0, 0.0};
}

std::array<double, MeshingParameters::size> MeshingParameters::upperBounds(double chord) {
  return {0.5 * chord, 0.5 * chord, 1.0, 0.9, 0.9, 1000.0, 5.0, 5.0};
}

MeshingParameters clipToRange(const MeshingParameters& p, double chord,
                              std::vector<std::string>* warnings, const std::string& source) {
  auto v = p.toArray();
  const auto lo = MeshingParameters::lowerBounds(chord), hi = MeshingParameters::upperBounds(chord);
  for (int k = 0; k < MeshingParameters::size; ++k) {
    const double clipped = std::clamp(v[k], lo[k], hi[k]);
    if (clipped != v[k] && warnings)
      warnings->push_back(source + ": <" + MeshingParameters::names()[k] + "> " +
                          formatExact(v[k]) + " is outside [" + formatExact(lo[k]) + ", " +
                          formatExact(hi[k]) + "], clipped to " + formatExact(clipped));
    v[k] = clipped;
  }
  return MeshingParameters::fromArray(v);
}

MeshingParameters readMeshDict(const std::filesystem::path& file, double chord,
                               std::vector<std::string>* warnings) {
  MeshingParameters p = MeshingParameters::defaults(chord);
  if (!std::filesystem::exists(file)) return p;
  readEntries(Dictionary::read(file, "meshDict", keys()), chord, p);
  return clipToRange(p, chord, warnings, file.string());
}

std::string meshDictXml(const MeshingParameters& p) {
  Dictionary dict("meshDict");
  dict.setComment("passageMesh meshing parameters; yIn, yOut in metres. See docs/case-format.md.");
  const auto v = p.toArray();
  for (int k = 0; k < MeshingParameters::size; ++k) {
    if (MeshingParameters::names()[k] == "nT")
      dict.set("nT", std::to_string(p.nT));
    else
      dict.set(MeshingParameters::names()[k], v[k]);
  }
  return dict.toXml();
}

void writeMeshDict(const std::filesystem::path& file, const MeshingParameters& p) {
  writeFileAtomically(file, meshDictXml(p));
}

}  // namespace passageMesh
