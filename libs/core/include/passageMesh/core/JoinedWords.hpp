#pragma once
// Lists of names in messages and files ("known: a, b, c", a policy's "splitIn splitOut"):
// written once here so that every tool spells its lists alike.
#include <string>

namespace passageMesh {

// The words of any range of strings (std::vector, std::array) in order, with `separator`
// between each two and none before the first or after the last; no words give "".
template <typename Words>
std::string joinedWords(const Words& words, const std::string& separator) {
  std::string text;
  bool first = true;
  for (const std::string& word : words) {
    text += (first ? "" : separator) + word;
    first = false;
  }
  return text;
}

}  // namespace passageMesh
