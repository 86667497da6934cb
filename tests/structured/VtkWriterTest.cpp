#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

#include "passageMesh/structured/VtkWriter.hpp"

using namespace passageMesh;

namespace {

std::filesystem::path freshDir(const std::string& name) {
  const auto dir =
      std::filesystem::path(PASSAGEMESH_BINARY_DIR) / "tests" / "structuredTestOutput" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Two sheared blocks with coordinates that need all 17 digits to round-trip.
StructuredMesh twoBlocks() {
  StructuredMesh mesh;
  for (auto [name, ni, nj, x0] :
       {std::tuple{"HInlet", 4, 3, 0.0}, std::tuple{"H&Out", 5, 3, 1.0}}) {
    StructuredBlock b{name, ni, nj, {}, {}};
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        b.x.push_back(x0 + i / 3.0);
        b.y.push_back(j / 7.0 + 0.1 * i);
      }
    mesh.blocks.push_back(b);
  }
  return mesh;
}

// cell (i, j) of block b gets 100 b + 10 j + i + 1/3
BlockField qualityField(const StructuredMesh& mesh) {
  BlockField field{"quality", {}};
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    field.values.emplace_back();
    for (int j = 0; j < mesh.blocks[b].nj - 1; ++j)
      for (int i = 0; i < mesh.blocks[b].ni - 1; ++i)
        field.values.back().push_back(100.0 * double(b) + 10 * j + i + 1.0 / 3.0);
  }
  return field;
}

std::vector<double> numbers(const char* text) {
  std::istringstream in(text ? text : "");
  std::vector<double> values;
  std::string word;
  while (in >> word) values.push_back(std::strtod(word.c_str(), nullptr));
  return values;
}

}  // namespace

TEST(VtkWriter, VtmReferencesOneVtsPerBlockWithExactPointsAndCellField) {
  const StructuredMesh mesh = twoBlocks();
  const auto dir = freshDir("vtk");
  writeVtm(mesh, dir / "passage.vtm", {qualityField(mesh)});

  tinyxml2::XMLDocument vtm;
  ASSERT_EQ(vtm.LoadFile((dir / "passage.vtm").c_str()), tinyxml2::XML_SUCCESS);
  const auto* root = vtm.FirstChildElement("VTKFile");
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->Attribute("type"), "vtkMultiBlockDataSet");
  std::vector<std::string> files, names;
  for (const auto* e =
           root->FirstChildElement("vtkMultiBlockDataSet")->FirstChildElement("DataSet");
       e; e = e->NextSiblingElement("DataSet")) {
    files.emplace_back(e->Attribute("file"));
    names.emplace_back(e->Attribute("name"));
  }
  EXPECT_EQ(files, (std::vector<std::string>{"passage/HInlet.vts", "passage/H&Out.vts"}));
  EXPECT_EQ(names, (std::vector<std::string>{"HInlet", "H&Out"}));

  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const StructuredBlock& block = mesh.blocks[b];
    SCOPED_TRACE(block.name);
    tinyxml2::XMLDocument vts;
    ASSERT_EQ(vts.LoadFile((dir / files[b]).c_str()), tinyxml2::XML_SUCCESS);
    const auto* grid = vts.FirstChildElement("VTKFile")->FirstChildElement("StructuredGrid");
    ASSERT_NE(grid, nullptr);
    const std::string extent =
        "0 " + std::to_string(block.ni - 1) + " 0 " + std::to_string(block.nj - 1) + " 0 0";
    EXPECT_EQ(std::string(grid->Attribute("WholeExtent")), extent);
    const auto* piece = grid->FirstChildElement("Piece");
    EXPECT_EQ(std::string(piece->Attribute("Extent")), extent);
    const auto points =
        numbers(piece->FirstChildElement("Points")->FirstChildElement("DataArray")->GetText());
    ASSERT_EQ(points.size(), 3 * block.x.size());
    for (std::size_t n = 0; n < block.x.size(); ++n) {
      ASSERT_EQ(points[3 * n], block.x[n]);  // exact: 17 significant digits
      ASSERT_EQ(points[3 * n + 1], block.y[n]);
      ASSERT_EQ(points[3 * n + 2], 0.0);
    }
    const auto* array = piece->FirstChildElement("CellData")->FirstChildElement("DataArray");
    ASSERT_NE(array, nullptr);
    EXPECT_STREQ(array->Attribute("Name"), "quality");
    const auto values = numbers(array->GetText());
    ASSERT_EQ(values.size(), std::size_t(block.ni - 1) * std::size_t(block.nj - 1));
    // cell (2, 1) sits at 2 + (ni - 1) * 1
    EXPECT_EQ(values[static_cast<std::size_t>(2 + (block.ni - 1))],
              100.0 * double(b) + 12 + 1.0 / 3.0);
  }
}

TEST(VtkWriter, WorksWithoutFieldsAndBesideNoFolder) {
  const auto dir = freshDir("vtkPlain");
  writeVtm(twoBlocks(), dir / "sub" / "grid.vtm");
  EXPECT_TRUE(std::filesystem::exists(dir / "sub" / "grid.vtm"));
  EXPECT_TRUE(std::filesystem::exists(dir / "sub" / "grid" / "HInlet.vts"));
  EXPECT_TRUE(std::filesystem::exists(dir / "sub" / "grid" / "H&Out.vts"));
}

TEST(VtkWriter, RejectsBadInputAndWritesNothing) {
  const auto dir = freshDir("vtkBad");
  auto expectRejected = [&](const StructuredMesh& mesh, const std::vector<BlockField>& fields,
                            const std::string& message) {
    try {
      writeVtm(mesh, dir / "passage.vtm", fields);
      ADD_FAILURE() << "no exception, expected: " << message;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << message;
  };
  StructuredMesh nan = twoBlocks();
  nan.blocks[1].x[5] = std::numeric_limits<double>::quiet_NaN();
  expectRejected(nan, {}, "block 'H&Out': non-finite coordinate");
  const StructuredMesh mesh = twoBlocks();
  BlockField shortField = qualityField(mesh);
  shortField.values[1].pop_back();
  expectRejected(mesh, {shortField}, "block 'H&Out' has 8 cells but 7 values");
  BlockField nanField = qualityField(mesh);
  nanField.values[0][0] = std::numeric_limits<double>::quiet_NaN();
  expectRejected(mesh, {nanField}, "non-finite value in block 'HInlet'");
  StructuredMesh slash = twoBlocks();
  slash.blocks[0].name = "a/b";
  expectRejected(slash, {}, "not usable as a file name");
  StructuredMesh duplicate = twoBlocks();
  duplicate.blocks[1].name = "HInlet";
  expectRejected(duplicate, {}, "duplicate block name");
}

TEST(VtkWriter, FileContentsAreWhatWriteVtmWritesWithTheVtmLast) {
  const auto dir = freshDir("contents");
  const StructuredMesh mesh = twoBlocks();
  const std::vector<BlockField> fields{qualityField(mesh)};
  writeVtm(mesh, dir / "mesh.vtm", fields);
  const auto contents = vtmFileContents(mesh, dir / "mesh.vtm", fields);
  ASSERT_EQ(contents.size(), mesh.blocks.size() + 1);  // one .vts per block, then the .vtm
  EXPECT_EQ(contents.back().first, dir / "mesh.vtm");
  for (const auto& [file, content] : contents) {
    std::ifstream in(file, std::ios::binary);
    ASSERT_TRUE(in) << file;
    const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(written, content) << file;
  }
  for (std::size_t k = 0; k + 1 < contents.size(); ++k) EXPECT_EQ(contents[k].first.extension(), ".vts");
}
