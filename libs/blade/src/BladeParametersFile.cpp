#include "passageMesh/blade/BladeParametersFile.hpp"

#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/blade/BladeValidity.hpp"
#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

namespace {

const std::vector<std::string> geometryKeys{"leadingEdge", "trailingEdge", "axialChord"};
const std::vector<std::string> reportKeys{
    "pointsFile", "points", "meanDeviation", "maxDeviation", "meanDeviationPercentChord",
    "maxDeviationPercentChord", "maxDeviationLine", "iterations", "starts", "seconds"};

std::string pair(const Eigen::Vector2d& p) { return formatExact(p.x()) + " " + formatExact(p.y()); }

}  // namespace

void writeBladeParametersFile(const std::filesystem::path& file, const BladeParameters& p,
                              const std::optional<BladeFitReport>& report) {
  writeFileAtomically(file, bladeParametersXml(p, report));
}

std::string bladeParametersXml(const BladeParameters& p,
                               const std::optional<BladeFitReport>& report) {
  Dictionary dict("bladeParameters");
  dict.setComment(
      "passageMesh blade shape parameters. Lengths in metres, angles in degrees from +x "
      "(counter-clockwise positive); distLe, distTe, radiusLe, radiusTe and thickness* are "
      "fractions of the chord. See docs/case-format.md.");
  Dictionary& shape = dict.addSection("shape");
  const auto values = p.toArray();
  for (int k = 0; k < BladeParameters::size; ++k) shape.set(BladeParameters::names()[k], values[k]);

  const BladeShape blade(p);
  Dictionary& geometry = dict.addSection("geometry");
  geometry.setComment("derived from the shape, for reference: edge points 'x y' [m]");
  geometry.set("leadingEdge", pair(blade.leadingEdge()));
  geometry.set("trailingEdge", pair(blade.trailingEdge()));
  geometry.set("axialChord", blade.trailingEdge().x() - blade.leadingEdge().x());

  if (report) {
    Dictionary& r = dict.addSection("fitReport");
    r.setComment("distances of the input points from the fitted profile");
    r.set("pointsFile", report->pointsFile);
    r.set("points", std::to_string(report->points));
    r.set("meanDeviation", report->meanDeviation);
    r.set("maxDeviation", report->maxDeviation);
    r.set("meanDeviationPercentChord", 100 * report->meanDeviation / p.chord);
    r.set("maxDeviationPercentChord", 100 * report->maxDeviation / p.chord);
    r.set("maxDeviationLine", std::to_string(report->maxDeviationLine));
    r.set("iterations", std::to_string(report->iterations));
    r.set("starts", std::to_string(report->starts));
    r.set("seconds", report->seconds);
  }
  return dict.toXml();
}

BladeParameters readBladeParametersFile(const std::filesystem::path& file) {
  const Dictionary dict =
      Dictionary::read(file, "bladeParameters", {}, {"shape", "geometry", "fitReport"});
  const Dictionary& shape = dict.section("shape");
  const auto& names = BladeParameters::names();
  shape.checkKeys(std::vector<std::string>(names.begin(), names.end()));
  if (dict.hasSection("geometry")) dict.section("geometry").checkKeys(geometryKeys);
  if (dict.hasSection("fitReport")) dict.section("fitReport").checkKeys(reportKeys);
  std::array<double, BladeParameters::size> v;
  for (int k = 0; k < BladeParameters::size; ++k) v[k] = shape.scalar(names[k]);
  const BladeParameters p = BladeParameters::fromArray(v);
  const BladeValidity validity = checkBladeValidity(BladeShape(p));
  if (!validity)
    throw InputError(file.string(), shape.line("xLe"),
                     "<shape> is not a valid blade: " + validity.reason);
  return p;
}

}  // namespace passageMesh
