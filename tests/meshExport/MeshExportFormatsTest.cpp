// The exporters' files: OpenFOAM polyMesh counts and ordering, Plot3D layout, the SU2
// CGNS zone read back with the CGNS library, format lists and staged outputs.
#include <cgnslib.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <utility>

#include "../TestFiles.hpp"
#include "../quality/QualityTestData.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/NumberFormat.hpp"
#include "passageMesh/meshExport/FoamPolyMesh.hpp"
#include "passageMesh/meshExport/MeshExport.hpp"
#include "passageMesh/meshExport/Plot3dFile.hpp"
#include "passageMesh/meshExport/Su2Cgns.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;
namespace fs = std::filesystem;

namespace {

// The list of an OpenFOAM file: its count and the items, one per line.
std::vector<std::string> foamList(const std::string& content, int& count) {
  std::istringstream in(content.substr(content.find("}\n\n") + 3));
  in >> count;
  std::string line;
  std::getline(in, line);
  std::getline(in, line);  // "("
  std::vector<std::string> items;
  while (std::getline(in, line) && line != ")") items.push_back(line);
  return items;
}

std::string fileNamed(const std::vector<std::pair<std::string, std::string>>& files, const std::string& name) {
  for (const auto& [n, c] : files)
    if (n == name) return c;
  return "";
}

}  // namespace

TEST(FoamPolyMesh, CountsAndUpperTriangularOrder) {
  const HohMesh hoh = validHohMesh();
  const UnstructuredPassage p = makeUnstructuredPassage(hoh.mesh);
  const auto files = foamPolyMeshFiles(p, 0.001);
  ASSERT_EQ(files.size(), 5u);
  int nPoints = 0, nFaces = 0, nOwners = 0, nNeighbours = 0, nPatches = 0;
  const auto points = foamList(fileNamed(files, "points"), nPoints);
  const auto faces = foamList(fileNamed(files, "faces"), nFaces);
  const auto owners = foamList(fileNamed(files, "owner"), nOwners);
  const auto neighbours = foamList(fileNamed(files, "neighbour"), nNeighbours);
  EXPECT_EQ(nPoints, static_cast<int>(2 * p.points.size()));
  EXPECT_EQ(static_cast<int>(points.size()), nPoints);
  std::size_t boundary = 0;
  for (const auto& e : p.patches) boundary += e.edges.size();
  EXPECT_EQ(nFaces, static_cast<int>(p.internalEdges.size() + boundary + 2 * p.cells.size()));
  EXPECT_EQ(static_cast<int>(faces.size()), nFaces);
  EXPECT_EQ(nOwners, nFaces);
  EXPECT_EQ(nNeighbours, static_cast<int>(p.internalEdges.size()));
  for (int k = 0; k < nNeighbours; ++k) {
    ASSERT_LT(std::stoi(owners[k]), std::stoi(neighbours[k]));
    if (k > 0 && owners[k] == owners[k - 1]) {
      ASSERT_LT(std::stoi(neighbours[k - 1]), std::stoi(neighbours[k]));
    }
  }
  const std::string boundaryFile = fileNamed(files, "boundary");
  foamList(boundaryFile, nPatches);
  EXPECT_EQ(nPatches, 6);
  for (const char* text : {"type            cyclic;", "neighbourPatch  periodicUpper;", "type            empty;",
                           "type            wall;", "transform       translational;"})
    EXPECT_NE(boundaryFile.find(text), std::string::npos) << text;
  // 17 significant digits: the first point reads back exactly.
  std::istringstream first(points[0].substr(1));
  double x = 0;
  first >> x;
  EXPECT_EQ(x, p.points[0].x());
}

TEST(Plot3dFile, BlocksExtrudedOneCellThick) {
  const HohMesh hoh = validHohMesh();
  std::istringstream in(plot3dAscii(hoh.mesh, 0.5));
  int blocks = 0;
  in >> blocks;
  ASSERT_EQ(blocks, 3);
  std::vector<int> dims(9);
  for (int& d : dims) in >> d;
  std::size_t values = 0;
  for (int b = 0; b < 3; ++b) {
    EXPECT_EQ(dims[3 * b], hoh.mesh.blocks[b].ni);
    EXPECT_EQ(dims[3 * b + 1], hoh.mesh.blocks[b].nj);
    EXPECT_EQ(dims[3 * b + 2], 2);
    values += 3u * 2u * static_cast<std::size_t>(dims[3 * b] * dims[3 * b + 1]);
  }
  double x0 = 0;
  in >> x0;
  EXPECT_EQ(x0, hoh.mesh.blocks[0].x[0]);
  std::size_t read = 1;
  for (double v; in >> v;) ++read;
  EXPECT_EQ(read, values);
}

TEST(Su2Cgns, ZoneReadsBackWithSectionsAndConfig) {
  const HohMesh hoh = validHohMesh();
  const UnstructuredPassage p = makeUnstructuredPassage(hoh.mesh);
  const fs::path file = tempFolder("meshExport") / "su2.cgns";
  fs::create_directories(file.parent_path());
  writeSu2Cgns(p, file);
  int fn = 0, nZones = 0, nSections = 0;
  ASSERT_EQ(cg_open(file.c_str(), CG_MODE_READ, &fn), CG_OK);
  ASSERT_EQ(cg_nzones(fn, 1, &nZones), CG_OK);
  EXPECT_EQ(nZones, 1);
  char name[33];
  cgsize_t size[3];
  ASSERT_EQ(cg_zone_read(fn, 1, 1, name, size), CG_OK);
  EXPECT_EQ(size[0], static_cast<cgsize_t>(p.points.size()));
  EXPECT_EQ(size[1], static_cast<cgsize_t>(p.cells.size()));
  ASSERT_EQ(cg_nsections(fn, 1, 1, &nSections), CG_OK);
  ASSERT_EQ(nSections, 6);
  const std::vector<std::pair<std::string, std::size_t>> expected = {
      {"cells", p.cells.size()}, {"blade", p.patches[0].edges.size()}, {"inlet", p.patches[1].edges.size()},
      {"outlet", p.patches[2].edges.size()}, {"periodicLower", p.patches[3].edges.size()},
      {"periodicUpper", p.patches[4].edges.size()}};
  for (int s = 1; s <= nSections; ++s) {
    CGNS_ENUMT(ElementType_t) type;
    cgsize_t start = 0, end = 0;
    int nBoundary = 0, parent = 0;
    ASSERT_EQ(cg_section_read(fn, 1, 1, s, name, &type, &start, &end, &nBoundary, &parent), CG_OK);
    EXPECT_EQ(name, expected[s - 1].first);
    EXPECT_EQ(static_cast<std::size_t>(end - start + 1), expected[s - 1].second) << name;
    EXPECT_EQ(type, s == 1 ? CGNS_ENUMV(QUAD_4) : CGNS_ENUMV(BAR_2)) << name;
  }
  // The periodic pair in CGNS's own form: lower node + translation = donor node.
  int nConnections = 0;
  ASSERT_EQ(cg_nconns(fn, 1, 1, &nConnections), CG_OK);
  ASSERT_EQ(nConnections, 1);
  CGNS_ENUMT(GridLocation_t) location;
  CGNS_ENUMT(GridConnectivityType_t) connectionType;
  CGNS_ENUMT(PointSetType_t) pointSet, donorSet;
  CGNS_ENUMT(ZoneType_t) donorZoneType;
  CGNS_ENUMT(DataType_t) donorDataType;
  cgsize_t nPoints = 0, nDonors = 0;
  char donorName[33];
  ASSERT_EQ(cg_conn_info(fn, 1, 1, 1, name, &location, &connectionType, &pointSet, &nPoints, donorName,
                         &donorZoneType, &donorSet, &donorDataType, &nDonors), CG_OK);
  EXPECT_EQ(std::string(donorName), "passage");
  EXPECT_EQ(connectionType, CGNS_ENUMV(Abutting1to1));
  ASSERT_EQ(nPoints, nDonors);
  EXPECT_EQ(static_cast<std::size_t>(nPoints), p.patches[3].edges.size() + 1);
  std::vector<cgsize_t> points(static_cast<std::size_t>(nPoints)), donors(static_cast<std::size_t>(nDonors));
  ASSERT_EQ(cg_conn_read(fn, 1, 1, 1, points.data(), CGNS_ENUMV(Integer), donors.data()), CG_OK);
  float centre[2], angle[2], shift[2];
  ASSERT_EQ(cg_conn_periodic_read(fn, 1, 1, 1, centre, angle, shift), CG_OK);
  EXPECT_FLOAT_EQ(shift[0], static_cast<float>(p.translation.x()));
  EXPECT_FLOAT_EQ(shift[1], static_cast<float>(p.translation.y()));
  EXPECT_NE(p.translation.y(), 0.0);
  for (std::size_t k = 0; k < points.size(); ++k)
    EXPECT_LT((p.points[static_cast<std::size_t>(points[k] - 1)] + p.translation -
               p.points[static_cast<std::size_t>(donors[k] - 1)]).norm(), 1e-12) << k;
  cg_close(fn);
  const std::string config = su2ConfigFragment(p, "su2.cgns");
  std::ostringstream translation;
  translation << "0.0, 0.0, 0.0, " << formatExact(p.translation.x()) << ", " << formatExact(p.translation.y());
  EXPECT_NE(config.find("MARKER_PERIODIC= ( periodicLower, periodicUpper, 0.0, 0.0, 0.0, " + translation.str()),
            std::string::npos) << config;
  EXPECT_NE(config.find("MARKER_HEATFLUX= ( blade, 0.0 )"), std::string::npos) << config;
}

TEST(ExportFormats, ParsedInOrderAndBadListsRefused) {
  EXPECT_EQ(parseExportFormats("plot3d,foam"), (std::vector{ExportFormat::plot3d, ExportFormat::foam}));
  EXPECT_EQ(parseExportFormats("su2cgns"), std::vector{ExportFormat::su2cgns});
  EXPECT_THROW(parseExportFormats("fluent"), InputError);
  EXPECT_THROW(parseExportFormats("foam,foam"), InputError);
  EXPECT_THROW(parseExportFormats(""), InputError);
  EXPECT_THROW(parseExportFormats("foam,"), InputError);
}

// Reads the Fortran records of plot3dBinary back (on a little-endian host, as CI's).
TEST(Plot3dFile, BinaryHoldsTheAsciiNumbersInFramedLittleEndianRecords) {
  static_assert(std::endian::native == std::endian::little, "this test reads host-order bytes");
  const HohMesh hoh = validHohMesh();
  const std::string bytes = plot3dBinary(hoh.mesh, 0.5);
  std::istringstream ascii(plot3dAscii(hoh.mesh, 0.5));
  std::size_t at = 0;
  const auto record = [&] {
    std::int32_t length = 0, end = 0;
    std::memcpy(&length, bytes.data() + at, 4);
    std::string payload = bytes.substr(at + 4, static_cast<std::size_t>(length));
    std::memcpy(&end, bytes.data() + at + 4 + length, 4);
    EXPECT_EQ(end, length);
    at += 8 + static_cast<std::size_t>(length);
    return payload;
  };
  const auto ints = [](const std::string& payload) {
    std::vector<std::int32_t> v(payload.size() / 4);
    std::memcpy(v.data(), payload.data(), payload.size());
    return v;
  };
  const std::vector<std::int32_t> count = ints(record());
  ASSERT_EQ(count, std::vector<std::int32_t>{3});
  const std::vector<std::int32_t> dims = ints(record());
  ASSERT_EQ(dims.size(), 9u);
  int asciiInt = 0;
  for (int i = 0; i < 10; ++i) {
    ascii >> asciiInt;
    EXPECT_EQ(asciiInt, i == 0 ? 3 : dims[static_cast<std::size_t>(i - 1)]);
  }
  for (int b = 0; b < 3; ++b) {
    const std::string payload = record();
    ASSERT_EQ(payload.size(), 8u * 3u * 2u * static_cast<std::size_t>(dims[3 * b] * dims[3 * b + 1]));
    for (std::size_t n = 0; n < payload.size() / 8; ++n) {
      double v = 0, expected = 0;
      std::memcpy(&v, payload.data() + 8 * n, 8);
      ascii >> expected;
      ASSERT_EQ(v, expected) << "block " << b << " value " << n;
    }
  }
  EXPECT_EQ(at, bytes.size());
}

TEST(MeshExport, AllFormatsWrittenIntoTheCase) {
  const HohMesh hoh = validHohMesh();
  const fs::path dir = tempFolder("exportCase");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto written = exportMesh(hoh.mesh, dir, {ExportFormat::foam, ExportFormat::plot3d, ExportFormat::su2cgns});
  EXPECT_EQ(written.size(), 5u);
  for (const auto& p : written) EXPECT_TRUE(fs::exists(dir / p)) << p;
  for (const char* f : {"points", "faces", "owner", "neighbour", "boundary"})
    EXPECT_TRUE(fs::exists(dir / "constant" / "polyMesh" / f)) << f;
}

// Whether su2CgnsFileWriter accepts a passage of this kind (an lvalue for a reference type).
template <typename Passage>
concept Su2WriterAccepts =
    requires(Passage&& passage) { su2CgnsFileWriter(std::forward<Passage>(passage), std::filesystem::path{}); };

TEST(Su2Cgns, FileWriterRefusesATemporaryPassage) {
  // The writer refers to the passage and runs later: a temporary would be gone by then.
  static_assert(Su2WriterAccepts<const UnstructuredPassage&>);
  static_assert(!Su2WriterAccepts<UnstructuredPassage>);
  static_assert(!Su2WriterAccepts<const UnstructuredPassage>);
}
