// exportMesh as a user runs it: all formats from a case's mesh; bad input (unknown
// format, missing mesh, a target that cannot be replaced) is one error line, exit 1, and
// nothing written.
#include <gtest/gtest.h>

#include "../quality/QualityTestData.hpp"
#include "UtilityTestSupport.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;

namespace {

const std::string exportMeshTool = EXPORTMESH_EXECUTABLE;

std::filesystem::path caseWithMesh(const std::string& name) {
  const auto dir = freshCase("exportMesh_" + name);
  const HohMesh hoh = validHohMesh();
  writeCgns(hoh.mesh, dir / "mesh" / "passage.cgns");
  return dir;
}

void expectOneErrorLine(const RunResult& r, const std::string& expected) {
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind("exportMesh: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

}  // namespace

TEST(ExportMeshCommand, WritesEveryFormat) {
  const auto dir = caseWithMesh("all");
  const RunResult r = runTool(exportMeshTool, dir, "-format foam,plot3d,su2cgns");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* f : {"constant/polyMesh/boundary", "constant/polyMesh/faces", "mesh/passage.xyz", "mesh/passage.x",
                        "mesh/passageSU2.cgns", "mesh/passageSU2.cfg"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
}

TEST(ExportMeshCommand, UnknownFormatIsAnErrorAndWritesNothing) {
  const auto dir = caseWithMesh("unknown");
  expectOneErrorLine(runTool(exportMeshTool, dir, "-format foam,fluent"), "unknown format 'fluent'");
  EXPECT_FALSE(std::filesystem::exists(dir / "constant" / "polyMesh"));
}

TEST(ExportMeshCommand, MissingMeshIsAnError) {
  const auto dir = freshCase("exportMesh_noMesh");
  expectOneErrorLine(runTool(exportMeshTool, dir, "-format foam"), "passage.cgns: file not found");
  EXPECT_FALSE(std::filesystem::exists(dir / "constant" / "polyMesh"));
}

TEST(ExportMeshCommand, UnreplaceableTargetWritesNothing) {
  // constant/polyMesh a plain file (what a root user's read-only target amounts to: the
  // rename cannot happen); the Plot3D file asked for first must not appear either.
  const auto dir = caseWithMesh("blocked");
  writeText(dir / "constant" / "polyMesh", "in the way\n");
  expectOneErrorLine(runTool(exportMeshTool, dir, "-format plot3d,foam"), "polyMesh: cannot replace");
  EXPECT_FALSE(std::filesystem::exists(dir / "mesh" / "passage.xyz"));
  EXPECT_EQ(readText(dir / "constant" / "polyMesh"), "in the way\n");
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

// A write that fails part way (a file size limit, as a full disk would) is one error line
// naming the target, exit 1, nothing written and no temporary left. Before, HDF5's exit
// handler crashed the tool after its error line (SIGSEGV), since the CGNS library had
// started HDF5 reading passage.cgns before its exit handler was turned off.
TEST(ExportMeshCommand, AFailedWriteIsOneLineAndWritesNothing) {
  const auto dir = caseWithMesh("limited");
  const RunResult r = runWithFileSizeLimit(exportMeshTool, "-case '" + dir.string() + "' -format su2cgns", dir, 8);
  expectOneErrorLine(r, "passageSU2.cgns: CGNS ");
  EXPECT_FALSE(std::filesystem::exists(dir / "mesh" / "passageSU2.cgns"));
  EXPECT_FALSE(std::filesystem::exists(dir / "mesh" / "passageSU2.cfg"));
  // A plain file too: the target and the reason, not a temporary's name.
  const RunResult p = runWithFileSizeLimit(exportMeshTool, "-case '" + dir.string() + "' -format plot3d", dir, 8);
  expectOneErrorLine(p, "mesh/passage.xyz: cannot write file (File too large)");
  EXPECT_FALSE(std::filesystem::exists(dir / "mesh" / "passage.xyz"));
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}
