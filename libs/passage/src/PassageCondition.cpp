#include "passageMesh/passage/PassageCondition.hpp"

#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/InputError.hpp"

namespace passageMesh {

PassageCondition readPassageDict(const std::filesystem::path& file, double chord,
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

  auto outside = [&](const std::string& key, double value, double lo, double hi,
                     const std::string& range) {
    if (warnings && (value < lo || value > hi))
      warnings->push_back(file.string() + ":" + std::to_string(dict.line(key)) + ": <" + key +
                          "> " + dict.text(key) + " is outside the method's range " + range);
  };
  using R = PassageConditionRange;
  outside("pitch", c.pitch / chord, R::pitchMin, R::pitchMax, "0.3c..1c");
  outside("xIn", c.xIn / chord, R::xInMin, R::xInMax, "0..1c");
  outside("xOut", c.xOut / chord, R::xOutMin, R::xOutMax, "0..1c");
  outside("nO", c.nO, R::nOMin, R::nOMax, "10000..50000");
  outside("firstCellHeight", c.firstCellHeight / chord, R::firstCellHeightMin,
          R::firstCellHeightMax, "2e-5c..2e-4c");
  return c;
}

}  // namespace passageMesh
