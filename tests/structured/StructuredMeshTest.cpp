#include "passageMesh/structured/StructuredMesh.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace passageMesh;

namespace {

StructuredMesh threeBlocks() {
  StructuredMesh mesh;
  for (const char* name : {"HInlet", "OBlock", "HOutlet"}) {
    StructuredBlock b;
    b.name = name;
    mesh.blocks.push_back(b);
  }
  return mesh;
}

}  // namespace

TEST(StructuredMesh, FindsABlockByName) {
  StructuredMesh mesh = threeBlocks();
  EXPECT_EQ(&mesh.block("OBlock"), &mesh.blocks[1]);
  EXPECT_EQ(&mesh.block("HOutlet"), &mesh.blocks[2]);
  mesh.block("HInlet").ni = 7;  // a reference into the mesh, not a copy
  EXPECT_EQ(mesh.blocks[0].ni, 7);
  const StructuredMesh& constMesh = mesh;
  EXPECT_EQ(&constMesh.block("HInlet"), &mesh.blocks[0]);
}

TEST(StructuredMesh, NamesTheMissingBlock) {
  const StructuredMesh mesh = threeBlocks();
  try {
    mesh.block("oblock");  // names are case-sensitive
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'oblock'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(StructuredMesh().block("OBlock"), std::invalid_argument);
}
