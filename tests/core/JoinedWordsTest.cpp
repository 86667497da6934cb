#include "passageMesh/core/JoinedWords.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

using namespace passageMesh;

TEST(JoinedWords, PutsTheSeparatorBetweenEachTwoWordsOnly) {
  using Words = std::vector<std::string>;
  EXPECT_EQ(joinedWords(Words{"nT", "nO", "nIn"}, ", "), "nT, nO, nIn");
  EXPECT_EQ(joinedWords(std::array<std::string, 2>{"splitIn", "splitOut"}, " "), "splitIn splitOut");
  EXPECT_EQ(joinedWords(Words{"alone"}, ", "), "alone");
  EXPECT_EQ(joinedWords(Words{}, ", "), "");
  // An empty word keeps its place (the old helpers skipped the separator after one).
  EXPECT_EQ(joinedWords(Words{"", "b"}, ","), ",b");
}
