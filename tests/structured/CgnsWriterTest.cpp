#include <cgnslib.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include "passageMesh/structured/CgnsWriter.hpp"

using namespace passageMesh;

namespace {

constexpr double pitch = 0.3;  // not exact in binary, so exactness checks mean something

std::filesystem::path testDir() {
  const auto dir =
      std::filesystem::path(PASSAGEMESH_BINARY_DIR) / "tests" / "structuredTestOutput";
  std::filesystem::create_directories(dir);
  return dir;
}

StructuredBlock block(const std::string& name, int ni, int nj) {
  StructuredBlock b{name, ni, nj, {}, {}};
  b.x.resize(static_cast<std::size_t>(ni * nj));
  b.y.resize(b.x.size());
  return b;
}

NodeRange range(int block, int i0, int j0, int i1, int j1) { return {block, {i0, j0}, {i1, j1}}; }

// A (4x3) and B (5x3) side by side, sheared, each periodic in y by `pitch`; C (8x3) a
// C-grid around a small triangle whose wake cut joins C to itself with reversed direction;
// O (9x3) an O-grid ring whose seam i = 0 <-> i = 8 joins it to itself, not periodically.
StructuredMesh syntheticMesh() {
  StructuredMesh mesh;
  StructuredBlock a = block("A", 4, 3), b = block("B", 5, 3), c = block("C", 8, 3);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i)
      a.xAt(i, j) = 0.25 * i, a.yAt(i, j) = 0.5 * pitch * j + 0.1 * a.xAt(i, j);
    for (int i = 0; i < 5; ++i)
      b.xAt(i, j) = 0.75 + 0.2 * i, b.yAt(i, j) = 0.5 * pitch * j + 0.1 * b.xAt(i, j);
  }
  const double wallX[8] = {2, 1, 0, -1, -1, 0, 1, 2}, wallY[8] = {0, 0, 0, -0.5, 0.5, 0, 0, 0};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 8; ++i) {
      c.xAt(i, j) = wallX[i] - (i >= 2 && i <= 5 ? 0.5 * j : 0.0);
      c.yAt(i, j) = wallY[i] + (i < 4 ? -0.5 : 0.5) * j;
    }
  StructuredBlock o = block("O", 9, 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 9; ++i) {
      const double angle = (i % 8) * std::acos(-1.0) / 4.0;  // i = 8 repeats i = 0 exactly
      o.xAt(i, j) = 5.0 + (1.0 + j) * std::cos(angle);
      o.yAt(i, j) = (1.0 + j) * std::sin(angle);
    }
  mesh.blocks = {a, b, c, o};
  const Eigen::Vector2d shift(0, pitch);
  mesh.connections = {{"AB", range(0, 3, 0, 3, 2), range(1, 0, 0, 0, 2), false, {0, 0}},
                      {"Aperiodic", range(0, 0, 0, 3, 0), range(0, 0, 2, 3, 2), true, shift},
                      {"Bperiodic", range(1, 4, 2, 0, 2), range(1, 4, 0, 0, 0), true, -shift},
                      {"wakeCut", range(2, 0, 0, 2, 0), range(2, 7, 0, 5, 0), false, {0, 0}},
                      {"seam", range(3, 0, 0, 0, 2), range(3, 8, 0, 8, 2), false, {0, 0}}};
  mesh.patches = {{"inlet", PatchType::inlet, range(0, 0, 2, 0, 0)},
                  {"outlet", PatchType::outlet, range(1, 4, 0, 4, 2)},
                  {"blade", PatchType::wall, range(2, 2, 0, 5, 0)},
                  {"farfield", PatchType::inlet, range(2, 0, 2, 7, 2)},
                  {"outlet", PatchType::outlet, range(2, 0, 0, 0, 2)},
                  {"outlet", PatchType::outlet, range(2, 7, 0, 7, 2)},
                  {"blade", PatchType::wall, range(3, 8, 0, 0, 0)}};
  return mesh;
}

// Reads a written file back through the CGNS mid-level library.
class CgnsReader {
 public:
  explicit CgnsReader(const std::filesystem::path& file) {
    if (cg_open(file.c_str(), CG_MODE_READ, &fn) != CG_OK) ADD_FAILURE() << cg_get_error();
  }
  ~CgnsReader() { cg_close(fn); }
  int fn = -1;
};

bool noFilesBeside(const std::filesystem::path& file) {
  for (const auto& entry : std::filesystem::directory_iterator(file.parent_path()))
    if (entry.path().filename().string().rfind(file.filename().string(), 0) == 0) return false;
  return true;
}

std::filesystem::path freshDir(const std::string& name) {
  const auto dir = testDir() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST(CgnsWriter, ZonesAndCoordinatesRoundTripExactly) {
  const StructuredMesh mesh = syntheticMesh();
  const auto file = freshDir("roundTrip") / "mesh.cgns";
  writeCgns(mesh, file);
  CgnsReader r(file);
  int nbases = 0, cellDim = 0, physDim = 0, nzones = 0;
  char name[33];
  ASSERT_EQ(cg_nbases(r.fn, &nbases), CG_OK);
  ASSERT_EQ(nbases, 1);
  ASSERT_EQ(cg_base_read(r.fn, 1, name, &cellDim, &physDim), CG_OK);
  EXPECT_EQ(cellDim, 2);
  EXPECT_EQ(physDim, 2);
  ASSERT_EQ(cg_nzones(r.fn, 1, &nzones), CG_OK);
  ASSERT_EQ(nzones, 4);
  for (int z = 1; z <= nzones; ++z) {
    const StructuredBlock& b = mesh.blocks[static_cast<std::size_t>(z - 1)];
    cgsize_t size[6];
    ASSERT_EQ(cg_zone_read(r.fn, 1, z, name, size), CG_OK);
    EXPECT_EQ(std::string(name), b.name);
    EXPECT_EQ(size[0], b.ni);
    EXPECT_EQ(size[1], b.nj);
    EXPECT_EQ(size[2], b.ni - 1);
    EXPECT_EQ(size[3], b.nj - 1);
    const cgsize_t lo[2] = {1, 1}, hi[2] = {b.ni, b.nj};
    std::vector<double> x(b.x.size()), y(b.y.size());
    ASSERT_EQ(cg_coord_read(r.fn, 1, z, "CoordinateX", CGNS_ENUMV(RealDouble), lo, hi, x.data()),
              CG_OK);
    ASSERT_EQ(cg_coord_read(r.fn, 1, z, "CoordinateY", CGNS_ENUMV(RealDouble), lo, hi, y.data()),
              CG_OK);
    EXPECT_EQ(x, b.x);
    EXPECT_EQ(y, b.y);
  }
}

TEST(CgnsWriter, ConnectionsInBothZonesWithTransformsThatMapNodeToNode) {
  const StructuredMesh mesh = syntheticMesh();
  const auto file = freshDir("connections") / "mesh.cgns";
  writeCgns(mesh, file);
  CgnsReader r(file);
  // A: AB + two periodic; B: likewise; C and O: their cut / seam twice
  const int expectedCount[4] = {3, 3, 2, 2};
  for (int z = 1; z <= 4; ++z) {
    const StructuredBlock& own = mesh.blocks[static_cast<std::size_t>(z - 1)];
    int n = 0;
    ASSERT_EQ(cg_n1to1(r.fn, 1, z, &n), CG_OK);
    EXPECT_EQ(n, expectedCount[z - 1]) << own.name;
    for (int c = 1; c <= n; ++c) {
      char name[33], donorName[33];
      cgsize_t rg[4], dr[4];
      int t[2];
      ASSERT_EQ(cg_1to1_read(r.fn, 1, z, c, name, donorName, rg, dr, t), CG_OK);
      SCOPED_TRACE(own.name + "/" + name);
      EXPECT_LE(rg[0], rg[2]);  // own range ascends
      EXPECT_LE(rg[1], rg[3]);
      const StructuredBlock* donor = nullptr;
      for (const auto& b : mesh.blocks)
        if (b.name == donorName) donor = &b;
      ASSERT_NE(donor, nullptr);
      Eigen::Vector2d shift(0, 0);
      float centre[2], angle[2], translation[2];
      const bool periodic =
          cg_1to1_periodic_read(r.fn, 1, z, c, centre, angle, translation) == CG_OK;
      if (periodic) {
        EXPECT_EQ(centre[0], 0.0f);
        EXPECT_EQ(angle[0], 0.0f);
        EXPECT_EQ(translation[0], 0.0f);
        // Zone A holds +pitch going up, -pitch coming back; B's connection was given downwards.
        EXPECT_EQ(std::abs(translation[1]), static_cast<float>(pitch));
        shift = Eigen::Vector2d(translation[0], translation[1]);
      }
      // The SIDS mapping: donor = T (own - ownBegin) + donorBegin. Every node must coincide,
      // and the node just outside the own face must map inside the donor.
      auto map = [&](int i, int j) {
        std::array<long, 2> d{dr[0], dr[1]};
        const long delta[2] = {i - rg[0], j - rg[1]};
        for (int k = 0; k < 2; ++k)
          d[static_cast<std::size_t>(std::abs(t[k]) - 1)] += (t[k] > 0 ? 1 : -1) * delta[k];
        return d;
      };
      for (long j = rg[1]; j <= rg[3]; ++j)
        for (long i = rg[0]; i <= rg[2]; ++i) {
          const auto d = map(static_cast<int>(i), static_cast<int>(j));
          ASSERT_GE(d[0], 1);
          ASSERT_LE(d[0], donor->ni);
          ASSERT_GE(d[1], 1);
          ASSERT_LE(d[1], donor->nj);
          const double tol = periodic ? 1e-7 : 1e-12;  // the translation is stored as float
          EXPECT_NEAR(own.xAt(int(i - 1), int(j - 1)) + shift.x(),
                      donor->xAt(int(d[0] - 1), int(d[1] - 1)), tol);
          EXPECT_NEAR(own.yAt(int(i - 1), int(j - 1)) + shift.y(),
                      donor->yAt(int(d[0] - 1), int(d[1] - 1)), tol);
        }
      const int normal = rg[0] == rg[2] ? 0 : 1;
      const int outward = rg[normal] == 1 ? -1 : 1;
      int ghost[2] = {static_cast<int>(rg[0]), static_cast<int>(rg[1])};
      ghost[normal] += outward;
      const auto inside = map(ghost[0], ghost[1]);
      EXPECT_TRUE(inside[0] >= 1 && inside[0] <= donor->ni && inside[1] >= 1 &&
                  inside[1] <= donor->nj);
    }
  }
  // The reversed self-connection: both entries flip both directions.
  char name[33], donorName[33];
  cgsize_t rg[4], dr[4];
  int t[2];
  ASSERT_EQ(cg_1to1_read(r.fn, 1, 3, 2, name, donorName, rg, dr, t), CG_OK);
  EXPECT_EQ(std::string(name), "wakeCut_reverse");
  EXPECT_EQ((std::vector<cgsize_t>(rg, rg + 4)), (std::vector<cgsize_t>{6, 1, 8, 1}));
  EXPECT_EQ((std::vector<cgsize_t>(dr, dr + 4)), (std::vector<cgsize_t>{3, 1, 1, 1}));
  EXPECT_EQ(t[0], -1);
  EXPECT_EQ(t[1], -2);
  // The O-grid seam: same directions on both sides, so the identity transform.
  ASSERT_EQ(cg_1to1_read(r.fn, 1, 4, 1, name, donorName, rg, dr, t), CG_OK);
  EXPECT_EQ(std::string(name), "seam");
  EXPECT_EQ(std::string(donorName), "O");
  EXPECT_EQ((std::vector<cgsize_t>(rg, rg + 4)), (std::vector<cgsize_t>{1, 1, 1, 3}));
  EXPECT_EQ((std::vector<cgsize_t>(dr, dr + 4)), (std::vector<cgsize_t>{9, 1, 9, 3}));
  EXPECT_EQ(t[0], 1);
  EXPECT_EQ(t[1], 2);
}

TEST(CgnsWriter, PeriodicTranslationsAreOppositeInTheTwoEntries) {
  const auto file = freshDir("periodic") / "mesh.cgns";
  writeCgns(syntheticMesh(), file);
  CgnsReader r(file);
  float centre[2], angle[2], first[2], second[2];
  ASSERT_EQ(cg_1to1_periodic_read(r.fn, 1, 1, 2, centre, angle, first), CG_OK);   // Aperiodic
  ASSERT_EQ(cg_1to1_periodic_read(r.fn, 1, 1, 3, centre, angle, second), CG_OK);  // _reverse
  EXPECT_EQ(first[1], static_cast<float>(pitch));
  EXPECT_EQ(second[1], -static_cast<float>(pitch));
  EXPECT_NE(cg_1to1_periodic_read(r.fn, 1, 1, 1, centre, angle, first), CG_OK);  // AB is not
}

TEST(CgnsWriter, BoundaryConditionsWithFamilies) {
  const auto file = freshDir("bcs") / "mesh.cgns";
  writeCgns(syntheticMesh(), file);
  CgnsReader r(file);
  struct Expected {
    int zone;
    std::string name, family;
    CGNS_ENUMT(BCType_t) type;
    std::vector<cgsize_t> range;
  };
  const std::vector<Expected> expected = {
      {1, "inlet", "inlet", CGNS_ENUMV(BCInflow), {1, 1, 1, 3}},
      {2, "outlet", "outlet", CGNS_ENUMV(BCOutflow), {5, 1, 5, 3}},
      {3, "blade", "blade", CGNS_ENUMV(BCWall), {3, 1, 6, 1}},
      {3, "farfield", "farfield", CGNS_ENUMV(BCInflow), {1, 3, 8, 3}},
      {3, "outlet", "outlet", CGNS_ENUMV(BCOutflow), {1, 1, 1, 3}},
      {3, "outlet_2", "outlet", CGNS_ENUMV(BCOutflow), {8, 1, 8, 3}},
      {4, "blade", "blade", CGNS_ENUMV(BCWall), {1, 1, 9, 1}}};
  int seen[5] = {0, 0, 0, 0, 0};
  for (const Expected& e : expected) {
    const int bc = ++seen[e.zone];
    char name[33];
    CGNS_ENUMT(BCType_t) type;
    CGNS_ENUMT(PointSetType_t) setType;
    cgsize_t npnts, normalSize;
    int normalIndex[2], ndataset;
    CGNS_ENUMT(DataType_t) normalType;
    ASSERT_EQ(cg_boco_info(r.fn, 1, e.zone, bc, name, &type, &setType, &npnts, normalIndex,
                           &normalSize, &normalType, &ndataset),
              CG_OK);
    EXPECT_EQ(std::string(name), e.name);
    EXPECT_EQ(type, e.type) << e.name;
    EXPECT_EQ(setType, CGNS_ENUMV(PointRange));
    ASSERT_EQ(npnts, 2);
    std::vector<cgsize_t> points(4);
    ASSERT_EQ(cg_boco_read(r.fn, 1, e.zone, bc, points.data(), nullptr), CG_OK);
    EXPECT_EQ(points, e.range) << e.name;
    ASSERT_EQ(cg_goto(r.fn, 1, "Zone_t", e.zone, "ZoneBC_t", 1, "BC_t", bc, "end"), CG_OK);
    char family[33];
    ASSERT_EQ(cg_famname_read(family), CG_OK);
    EXPECT_EQ(std::string(family), e.family);
  }
  for (int z = 1; z <= 4; ++z) {
    int n = 0;
    ASSERT_EQ(cg_nbocos(r.fn, 1, z, &n), CG_OK);
    EXPECT_EQ(n, seen[z]);
  }
  int nfamilies = 0;
  ASSERT_EQ(cg_nfamilies(r.fn, 1, &nfamilies), CG_OK);
  ASSERT_EQ(nfamilies, 4);  // inlet, outlet, blade, farfield
  const std::vector<std::pair<std::string, CGNS_ENUMT(BCType_t)>> families = {
      {"inlet", CGNS_ENUMV(BCInflow)},
      {"outlet", CGNS_ENUMV(BCOutflow)},
      {"blade", CGNS_ENUMV(BCWall)},
      {"farfield", CGNS_ENUMV(BCInflow)}};
  for (int f = 1; f <= nfamilies; ++f) {
    char name[33], bcName[33];
    int nbc = 0, ngeo = 0;
    CGNS_ENUMT(BCType_t) type;
    ASSERT_EQ(cg_family_read(r.fn, 1, f, name, &nbc, &ngeo), CG_OK);
    ASSERT_EQ(nbc, 1);
    ASSERT_EQ(cg_fambc_read(r.fn, 1, f, 1, bcName, &type), CG_OK);
    EXPECT_EQ(std::string(name), families[static_cast<std::size_t>(f - 1)].first);
    EXPECT_EQ(type, families[static_cast<std::size_t>(f - 1)].second) << name;
  }
}

TEST(CgnsWriter, CgnscheckFindsNothingToReport) {
  if (std::system("command -v cgnscheck >/dev/null 2>&1") != 0) GTEST_SKIP() << "no cgnscheck";
  const auto dir = freshDir("cgnscheck");
  const auto file = dir / "mesh.cgns", report = dir / "cgnscheck.txt";
  writeCgns(syntheticMesh(), file);
  const std::string command = "cgnscheck '" + file.string() + "' > '" + report.string() + "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::stringstream out;
  out << std::ifstream(report).rdbuf();
  const std::string text = out.str();
  EXPECT_NE(text.find("checking base"), std::string::npos) << text;  // it did check
  // cgnscheck prints "WARNING:..." / "ERROR:..." lines and a "N warnings" summary.
  std::string lower = text;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  EXPECT_EQ(lower.find("warning"), std::string::npos) << text;
  EXPECT_EQ(lower.find("error"), std::string::npos) << text;
}

TEST(CgnsWriter, RejectsBadInputAndLeavesNoFile) {
  const auto dir = freshDir("bad");
  const auto file = dir / "mesh.cgns";
  auto expectRejected = [&](const StructuredMesh& mesh, const std::string& message) {
    try {
      writeCgns(mesh, file);
      ADD_FAILURE() << "no exception, expected: " << message;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
    EXPECT_TRUE(noFilesBeside(file)) << message;
  };
  StructuredMesh nan = syntheticMesh();
  nan.blocks[1].yAt(2, 1) = std::numeric_limits<double>::quiet_NaN();
  expectRejected(nan, "block 'B': non-finite coordinate at node (2,1)");
  StructuredMesh counts = syntheticMesh();
  counts.connections[0].b = range(1, 0, 0, 0, 1);
  expectRejected(counts, "connection 'AB': side a has 3 nodes, side b 2");
  StructuredMesh interior = syntheticMesh();
  interior.patches[0].range = range(0, 1, 0, 1, 2);
  expectRejected(interior, "patch 'inlet': range block 0 (1,0)-(1,2) is not on a block edge");
  StructuredMesh reversed = syntheticMesh();
  std::swap(reversed.connections[0].b.begin, reversed.connections[0].b.end);
  expectRejected(reversed, "connection 'AB': node 0 of side a does not coincide");
  StructuredMesh mixedFamily = syntheticMesh();
  mixedFamily.patches[5].type = PatchType::wall;
  expectRejected(mixedFamily, "patches of one name must have one type");
}

TEST(CgnsWriter, FailedWriteKeepsThePreviousFileAndNamesTheFile) {
  const auto dir = freshDir("replace");
  const auto file = dir / "mesh.cgns";
  writeCgns(syntheticMesh(), file);
  const auto sizeBefore = std::filesystem::file_size(file);
  StructuredMesh nan = syntheticMesh();
  nan.blocks[0].x[0] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(writeCgns(nan, file), std::invalid_argument);
  EXPECT_EQ(std::filesystem::file_size(file), sizeBefore);
  CgnsReader r(file);
  int nzones = 0;
  EXPECT_EQ(cg_nzones(r.fn, 1, &nzones), CG_OK);
  EXPECT_EQ(nzones, 4);

  std::ofstream(dir / "notADirectory") << "x";
  const auto impossible = dir / "notADirectory" / "mesh.cgns";
  try {
    writeCgns(syntheticMesh(), impossible);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(impossible.string()), std::string::npos) << e.what();
  }
}

// Whether cgnsFileWriter accepts a mesh of this kind (an lvalue for a reference type).
template <typename Mesh>
concept WriterAccepts = requires(Mesh&& mesh) { cgnsFileWriter(std::forward<Mesh>(mesh), std::filesystem::path{}); };

TEST(CgnsWriter, FileWriterRefusesATemporaryMesh) {
  // The writer refers to the mesh and runs later: a temporary would be gone by then.
  static_assert(WriterAccepts<const StructuredMesh&>);
  static_assert(!WriterAccepts<StructuredMesh>);
  static_assert(!WriterAccepts<const StructuredMesh>);
}
