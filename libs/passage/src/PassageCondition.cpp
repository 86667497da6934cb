#include "passageMesh/passage/PassageCondition.hpp"

#include <iomanip>
#include <sstream>

#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/NumberFormat.hpp"
#include "passageMesh/passage/PassageBoundary.hpp"

namespace passageMesh {

namespace {

// readPassageDict, with the pitch also refused at or below `blade`'s widest extent in y
// when a blade is given.
PassageCondition readCondition(const std::filesystem::path& file, double chord, const BladeShape* blade,
                               std::vector<std::string>* warnings) {
  const std::vector<std::string> keys{"pitch", "xIn", "xOut", "nO", "firstCellHeight"};
  const Dictionary dict = Dictionary::read(file, "passageDict", keys);
  dict.require(keys);
  PassageCondition c;
  c.pitch = dict.length("pitch", chord);
  c.xIn = dict.length("xIn", chord);
  c.xOut = dict.length("xOut", chord);
  const long nO = dict.integer("nO");
  c.firstCellHeight = dict.length("firstCellHeight", chord);

  auto refuse = [&](const std::string& key, const std::string& expected) {
    throw InputError(file.string(), dict.line(key),
                     "<" + key + "> " + dict.text(key) + ": expected " + expected);
  };
  if (c.pitch <= 0) refuse("pitch", "a positive length");
  if (c.xIn < 0) refuse("xIn", "a length >= 0");
  if (c.xOut < 0) refuse("xOut", "a length >= 0");
  if (nO < 100 || nO > 10000000) refuse("nO", "an integer from 100 to 10000000");
  if (c.firstCellHeight <= 0) refuse("firstCellHeight", "a positive length");
  c.nO = static_cast<int>(nO);
  if (blade) {
    const BladeYExtent widest = widestYExtent(*blade);
    if (c.pitch <= widest.extent) {
      // The bound exactly (formatShortest: a pitch written as printed above it passes) and in chords.
      std::ostringstream expected;
      expected << "a pitch above " << formatShortest(widest.extent) << " m (" << std::setprecision(4)
               << widest.extent / chord << "c), the blade's extent in y at x = " << std::setprecision(6) << widest.x
               << " m (at this pitch the blade overlaps its periodic neighbour: no passage exists)";
      refuse("pitch", expected.str());
    }
  }

  // A length is compared in chords; the warning says the value in chords too, since the
  // dictionary may give it in metres ("0.1" for STD10's pitch is 1.008c).
  auto outside = [&](const std::string& key, double value, double lo, double hi,
                     const std::string& range, bool inChords) {
    if (!warnings || (value >= lo && value <= hi)) return;
    std::ostringstream given;
    given << dict.text(key);
    if (inChords) given << " (" << std::setprecision(4) << value << "c)";
    warnings->push_back(file.string() + ":" + std::to_string(dict.line(key)) + ": <" + key +
                        "> " + given.str() + " is outside the method's range " + range);
  };
  using R = PassageConditionRange;
  outside("pitch", c.pitch / chord, R::pitchMin, R::pitchMax, "0.3c..1c", true);
  outside("xIn", c.xIn / chord, R::xInMin, R::xInMax, "0..1c", true);
  outside("xOut", c.xOut / chord, R::xOutMin, R::xOutMax, "0..1c", true);
  outside("nO", c.nO, R::nOMin, R::nOMax, "10000..50000", false);
  outside("firstCellHeight", c.firstCellHeight / chord, R::firstCellHeightMin,
          R::firstCellHeightMax, "2e-5c..2e-4c", true);
  return c;
}

}  // namespace

PassageCondition readPassageDict(const std::filesystem::path& file, double chord,
                                 std::vector<std::string>* warnings) {
  return readCondition(file, chord, nullptr, warnings);
}

PassageCondition readPassageDict(const std::filesystem::path& file, const BladeShape& blade,
                                 std::vector<std::string>* warnings) {
  return readCondition(file, blade.parameters().chord, &blade, warnings);
}

}  // namespace passageMesh
