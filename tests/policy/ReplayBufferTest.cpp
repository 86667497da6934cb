#include "passageMesh/policy/ReplayBuffer.hpp"

#include <gtest/gtest.h>

using namespace passageMesh;

namespace {

void addEpisode(ReplayBuffer& b, double v) { b.add({v, -v}, {2 * v}, v); }

}  // namespace

TEST(ReplayBuffer, KeepsTheNewestEpisodesUpToItsCapacity) {
  ReplayBuffer b(2, 1, 3);
  for (int i = 1; i <= 5; ++i) addEpisode(b, i);
  EXPECT_EQ(b.size(), 3);
  EXPECT_EQ(b.recentRewards(10), (std::vector<double>{5, 4, 3}));
  PolicyBatch s, a;
  Eigen::VectorXd r;
  b.exportEpisodes(s, a, r);
  EXPECT_EQ(r, Eigen::Vector3d(3, 4, 5));
  EXPECT_EQ(s(2, 1), -5);
  EXPECT_EQ(a(0, 0), 6);
  EXPECT_THROW(b.add({1.0}, {1.0}, 0.0), std::invalid_argument);
}

TEST(ReplayBuffer, SamplesOnlyStoredEpisodesAndARebuiltBufferSamplesTheSame) {
  ReplayBuffer b(2, 1, 50);
  for (int i = 0; i < 80; ++i) addEpisode(b, i);
  PolicyBatch s, a, s2, a2;
  Eigen::VectorXd r, r2;
  std::mt19937_64 rng(3);
  b.sample(500, rng, s, a, r);
  for (int i = 0; i < 500; ++i) {
    EXPECT_GE(r[i], 30);  // the oldest 30 were overwritten
    EXPECT_EQ(s(i, 0), r[i]);
    EXPECT_EQ(a(i, 0), 2 * r[i]);
  }
  ReplayBuffer copy(2, 1, 50);
  b.exportEpisodes(s, a, r);
  copy.importEpisodes(s, a, r);
  std::mt19937_64 rngA(9), rngB(9);
  b.sample(100, rngA, s, a, r);
  copy.sample(100, rngB, s2, a2, r2);
  EXPECT_EQ(r, r2);
  addEpisode(b, 100);
  addEpisode(copy, 100);
  EXPECT_EQ(b.recentRewards(50), copy.recentRewards(50));
}
