// readCgns gives back what writeCgns wrote: the same nodes, connections (periodic
// translations included) and patches; missing or broken files are input errors.
#include "passageMesh/structured/CgnsReader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "../TestFiles.hpp"
#include "../blade/BladeTestData.hpp"
#include "../passage/PassageTestData.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"

using namespace passageMesh;

namespace {

using NodePair = std::array<int, 6>;  // block, i, j of side a; block, i, j of side b

std::set<NodePair> nodePairs(const BlockConnection& c, bool swapped) {
  auto step = [](const NodeRange& r) {
    auto sign = [](int v) { return (v > 0) - (v < 0); };
    return std::array<int, 2>{sign(r.end[0] - r.begin[0]), sign(r.end[1] - r.begin[1])};
  };
  const auto sa = step(c.a), sb = step(c.b);
  const int n = std::abs(c.a.end[0] - c.a.begin[0]) + std::abs(c.a.end[1] - c.a.begin[1]) + 1;
  std::set<NodePair> pairs;
  for (int k = 0; k < n; ++k) {
    const std::array<int, 3> a{c.a.block, c.a.begin[0] + k * sa[0], c.a.begin[1] + k * sa[1]};
    const std::array<int, 3> b{c.b.block, c.b.begin[0] + k * sb[0], c.b.begin[1] + k * sb[1]};
    const auto& first = swapped ? b : a;
    const auto& second = swapped ? a : b;
    pairs.insert({first[0], first[1], first[2], second[0], second[1], second[2]});
  }
  return pairs;
}

// The same node pairs and translation, whichever side is called a.
void expectEquivalent(const BlockConnection& read, const BlockConnection& written, double length) {
  EXPECT_EQ(read.periodic, written.periodic) << written.name;
  const bool sameSides = nodePairs(read, false) == nodePairs(written, false);
  const bool swappedSides = nodePairs(read, true) == nodePairs(written, false);
  EXPECT_TRUE(sameSides || swappedSides) << written.name;
  const Eigen::Vector2d expected = sameSides ? written.translation : Eigen::Vector2d(-written.translation);
  EXPECT_LT((read.translation - expected).norm(), 1e-14 * length) << written.name;
}

StructuredMesh hohMesh() {
  const BladeShape blade(testData::typicalTurbineBlade());
  const double chord = blade.parameters().chord;
  PassageCondition condition = testData::paperCondition(chord);
  condition.nO = 3000;
  MeshingParameters parameters = MeshingParameters::defaults(chord);
  parameters.nT = 100;
  return buildHohMesh(blade, condition, parameters).mesh;
}

}  // namespace

TEST(CgnsReader, RoundTripGivesTheSameMesh) {
  const StructuredMesh written = hohMesh();
  const auto file = testData::tempFolder("cgnsReader") / "passage.cgns";
  writeCgns(written, file);
  const StructuredMesh read = readCgns(file);

  ASSERT_EQ(read.blocks.size(), written.blocks.size());
  for (std::size_t b = 0; b < written.blocks.size(); ++b) {
    EXPECT_EQ(read.blocks[b].name, written.blocks[b].name);
    EXPECT_EQ(read.blocks[b].ni, written.blocks[b].ni);
    EXPECT_EQ(read.blocks[b].nj, written.blocks[b].nj);
    EXPECT_EQ(read.blocks[b].x, written.blocks[b].x);  // bit for bit (RealDouble)
    EXPECT_EQ(read.blocks[b].y, written.blocks[b].y);
  }
  ASSERT_EQ(read.connections.size(), written.connections.size());
  const double chord = testData::typicalTurbineBlade().chord;
  for (const BlockConnection& w : written.connections) {
    const auto r = std::find_if(read.connections.begin(), read.connections.end(),
                                [&](const BlockConnection& c) { return c.name == w.name; });
    ASSERT_NE(r, read.connections.end()) << w.name;
    expectEquivalent(*r, w, chord);
  }
  ASSERT_EQ(read.patches.size(), written.patches.size());
  for (const BoundaryPatch& w : written.patches) {
    const auto r = std::find_if(read.patches.begin(), read.patches.end(),
                                [&](const BoundaryPatch& p) { return p.name == w.name; });
    ASSERT_NE(r, read.patches.end()) << w.name;
    EXPECT_EQ(r->type, w.type);
    EXPECT_EQ(r->range.block, w.range.block);
    EXPECT_EQ(r->range.begin, w.range.begin);
    EXPECT_EQ(r->range.end, w.range.end);
  }
}

TEST(CgnsReader, MissingOrBrokenFileIsAnInputError) {
  const auto missing = testData::tempFolder("cgnsReader") / "missing.cgns";
  try {
    readCgns(missing);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing.string() + ": file not found");
  }
  const auto text = testData::writeTempFile("cgnsReader", "text.cgns", "not a mesh\n");
  try {
    readCgns(text);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(text.string() + ": not a CGNS file"), std::string::npos)
        << e.what();
  }
}
