#include "passageMesh/meshExport/FoamPolyMesh.hpp"

#include <sstream>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

namespace {

std::string header(const std::string& foamClass, const std::string& object, const std::string& note = "") {
  return "/*--------------------------------*- C++ -*----------------------------------*\\\n"
         "  written by passageMesh exportMesh\n"
         "\\*---------------------------------------------------------------------------*/\n"
         "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       " + foamClass +
         ";\n" + (note.empty() ? "" : "    note        \"" + note + "\";\n") +
         "    location    \"constant/polyMesh\";\n    object      " + object + ";\n}\n\n";
}

std::string vector3(double x, double y, double z) {
  std::string text = "(";  // (appended in steps: GCC 12 warns falsely (-Wrestrict) on "(" + string)
  text += formatExact(x);
  text += ' ';
  text += formatExact(y);
  text += ' ';
  text += formatExact(z);
  text += ')';
  return text;
}

const char* foamType(EdgePatchKind kind) {
  switch (kind) {
    case EdgePatchKind::wall: return "wall";
    case EdgePatchKind::inlet:
    case EdgePatchKind::outlet: return "patch";
    default: return "cyclic";
  }
}

// The faces with their owner and neighbour cells, in file order.
struct FaceList {
  std::ostringstream faces, owners, neighbours;
  int count = 0, internal = 0;

  // An edge extruded: p0, p1 at z = 0, then p1, p0 at z = thickness (offset n). With the
  // owner to the left of p0 -> p1 this face's normal points out of the owner.
  // startAtP1: the same face, its vertex list rotated to start at p1. OpenFOAM pairs
  // vertex 0 of a cyclic face with vertex 0 of its partner (the rest in reverse order);
  // the partner's edge runs the other way round, so its vertex 0 is its p1.
  void addEdge(const MeshEdge& e, int n, bool startAtP1 = false) {
    if (startAtP1) faces << "4(" << e.p1 << ' ' << e.p1 + n << ' ' << e.p0 + n << ' ' << e.p0 << ")\n";
    else faces << "4(" << e.p0 << ' ' << e.p1 << ' ' << e.p1 + n << ' ' << e.p0 + n << ")\n";
    owners << e.owner << '\n';
    if (e.neighbour >= 0) neighbours << e.neighbour << '\n';
    ++count;
  }
  void addQuad(const std::array<int, 4>& q, int owner) {
    faces << "4(" << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << ")\n";
    owners << owner << '\n';
    ++count;
  }
};

std::string list(const std::string& items, int count) {
  return std::to_string(count) + "\n(\n" + items + ")\n";
}

}  // namespace

std::vector<std::pair<std::string, std::string>> foamPolyMeshFiles(const UnstructuredPassage& passage,
                                                                   double thickness) {
  const int n = static_cast<int>(passage.points.size());
  const int nCells = static_cast<int>(passage.cells.size());
  std::ostringstream points;
  for (const double z : {0.0, thickness})
    for (const auto& p : passage.points) points << vector3(p.x(), p.y(), z) << '\n';

  FaceList f;
  for (const MeshEdge& e : passage.internalEdges) f.addEdge(e, n);
  f.internal = f.count;
  std::ostringstream boundary;
  const auto entry = [&](const std::string& name, const std::string& type, int faces, int start,
                         const std::string& extra) {
    boundary << "    " << name << "\n    {\n        type            " << type << ";\n"
             << "        inGroups        List<word> 1(" << type << ");\n"
             << "        nFaces          " << faces << ";\n        startFace       " << start << ";\n"
             << extra << "    }\n";
  };
  for (const EdgePatch& p : passage.patches) {
    const int start = f.count;
    for (const MeshEdge& e : p.edges) f.addEdge(e, n, p.kind == EdgePatchKind::periodicUpper);
    std::string extra;
    if (p.kind == EdgePatchKind::periodicLower || p.kind == EdgePatchKind::periodicUpper) {
      const bool lower = p.kind == EdgePatchKind::periodicLower;
      const Eigen::Vector2d s = lower ? passage.translation : Eigen::Vector2d(-passage.translation);
      extra = "        matchTolerance  0.0001;\n        transform       translational;\n"
              "        neighbourPatch  " + std::string(lower ? "periodicUpper" : "periodicLower") + ";\n"
              "        separationVector " + vector3(s.x(), s.y(), 0) + ";\n";
    }
    entry(p.name, foamType(p.kind), f.count - start, start, extra);
  }
  const int frontStart = f.count;
  for (int c = 0; c < nCells; ++c) {  // z = 0, normal -z: the corners turned around
    const auto& q = passage.cells[static_cast<std::size_t>(c)];
    f.addQuad({q[0], q[3], q[2], q[1]}, c);
  }
  for (int c = 0; c < nCells; ++c) {
    const auto& q = passage.cells[static_cast<std::size_t>(c)];
    f.addQuad({q[0] + n, q[1] + n, q[2] + n, q[3] + n}, c);
  }
  entry("frontAndBack", "empty", f.count - frontStart, frontStart, "");

  const std::string note = "nPoints:" + std::to_string(2 * n) + " nCells:" + std::to_string(nCells) +
                           " nFaces:" + std::to_string(f.count) +
                           " nInternalFaces:" + std::to_string(f.internal);
  return {{"points", header("vectorField", "points") + list(points.str(), 2 * n)},
          {"faces", header("faceList", "faces") + list(f.faces.str(), f.count)},
          {"owner", header("labelList", "owner", note) + list(f.owners.str(), f.count)},
          {"neighbour", header("labelList", "neighbour", note) + list(f.neighbours.str(), f.internal)},
          {"boundary", header("polyBoundaryMesh", "boundary") +
                           list(boundary.str(), static_cast<int>(passage.patches.size()) + 1)}};
}

void writeFoamPolyMesh(const UnstructuredPassage& passage, double thickness,
                       const std::filesystem::path& directory) {
  for (const auto& [name, content] : foamPolyMeshFiles(passage, thickness))
    fileWithContent(directory / name, content).write(directory / name);  // (the directory is staged whole)
}

}  // namespace passageMesh
