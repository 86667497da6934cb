// plotMesh's pictures: the gnuplot data, the PNGs (when gnuplot is installed), and that a
// missing gnuplot is a one-line error that replaces nothing.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "../TestFiles.hpp"
#include "../quality/QualityTestData.hpp"
#include "passageMesh/plot/MeshPictures.hpp"
#include "passageMesh/plot/MeshPlotData.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;
namespace fs = std::filesystem;

namespace {

int countLines(const std::string& text, bool blank) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.empty() == blank;
  return n;
}

bool isPng(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  return std::string(magic + 1, 3) == "PNG";
}

}  // namespace

TEST(MeshPlotData, GridLinesEverySecondPlusEdges) {
  StructuredMesh mesh;
  mesh.blocks = {tensorBlock("B", {0, 1, 2, 3}, {0, 1, 2})};
  const std::string every = gridLinesData(mesh, 1);
  EXPECT_EQ(countLines(every, true), 3 + 4);            // one blank line after each grid line
  EXPECT_EQ(countLines(every, false), 3 * 4 + 4 * 3);
  const std::string second = gridLinesData(mesh, 2);
  EXPECT_EQ(countLines(second, true), 2 + 3);           // j 0, 2; i 0, 2, 3 (the edge)
  EXPECT_EQ(countLines(nodeRowData(mesh.blocks[0], 0), false), 4);
  const std::string cells = cellValuesData(mesh.blocks[0], {0, 1, 2, 3, 4, 5});
  EXPECT_EQ(countLines(cells, true), 6);
  EXPECT_EQ(countLines(cells, false), 24);
  EXPECT_NE(cells.find("1 1 4\n"), std::string::npos);  // cell (1, 1) = value 4, corner (1, 1)
}

TEST(MeshPictures, EveryPictureIsAPng) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
  const HohMesh hoh = validHohMesh();
  const MeshQuality q = computeMeshQuality(hoh.mesh, {.everyBlock = true});
  BladeCurves blade;
  for (int i = 0; i < hoh.mesh.blocks[1].ni; ++i)
    blade.profile.emplace_back(hoh.mesh.blocks[1].xAt(i, 0), hoh.mesh.blocks[1].yAt(i, 0));
  blade.inputPoints = blade.profile;
  const fs::path folder = tempFolder("plots");
  fs::remove_all(folder);
  const auto pictures = drawMeshPictures(hoh.mesh, q, &blade, folder);
  EXPECT_EQ(pictures.size(), 6u);
  for (const auto& p : pictures) EXPECT_TRUE(isPng(p)) << p;
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 6) << "temporaries left";
}

TEST(MeshPictures, MissingGnuplotReplacesNothing) {
  const HohMesh hoh = validHohMesh();
  const MeshQuality q = computeMeshQuality(hoh.mesh, {.everyBlock = true});
  const fs::path folder = tempFolder("noPlots");
  fs::remove_all(folder);
  try {
    drawMeshPictures(hoh.mesh, q, nullptr, folder, "noSuchGnuplotProgram");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("noSuchGnuplotProgram is not installed"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(folder / "passage.png"));
  EXPECT_THROW(drawMeshPictures(hoh.mesh, computeMeshQuality(hoh.mesh), nullptr, folder), std::invalid_argument);
}
