#include "passageMesh/structured/CgnsWriter.hpp"

#include <cgnslib.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "passageMesh/structured/CgnsLibrary.hpp"

namespace passageMesh {
namespace {

// CGNS node names hold at most 32 characters and '/' separates path components.
constexpr std::size_t maxCgnsName = 32;

void checkName(const std::string& name, const std::string& what) {
  if (name.empty()) throw std::invalid_argument(what + ": empty name");
  if (name.size() > maxCgnsName)
    throw std::invalid_argument(what + " '" + name + "': longer than 32 characters (CGNS limit)");
  if (name.find('/') != std::string::npos)
    throw std::invalid_argument(what + " '" + name + "': '/' is not allowed in a CGNS name");
}

// Where a node range lies on its block and which way it runs.
struct Face {
  int normalAxis = 0;  // index direction across the face: 0 = i, 1 = j
  int outward = 0;     // +1 on the block's max side (i = ni - 1 or j = nj - 1), -1 on its min side
  int alongAxis = 1;   // index direction along the face
  int alongSign = 1;   // +1 when the range runs towards larger indices
  int nodeCount = 0;
};

std::string describe(const NodeRange& r) {
  return "block " + std::to_string(r.block) + " (" + std::to_string(r.begin[0]) + "," +
         std::to_string(r.begin[1]) + ")-(" + std::to_string(r.end[0]) + "," +
         std::to_string(r.end[1]) + ")";
}

Face faceOf(const StructuredMesh& mesh, const NodeRange& r, const std::string& what) {
  if (r.block < 0 || r.block >= static_cast<int>(mesh.blocks.size()))
    throw std::invalid_argument(what + ": no block " + std::to_string(r.block));
  const StructuredBlock& block = mesh.blocks[static_cast<std::size_t>(r.block)];
  const std::array<int, 2> size{block.ni, block.nj};
  for (int axis = 0; axis < 2; ++axis)
    for (int index : {r.begin[axis], r.end[axis]})
      if (index < 0 || index >= size[axis])
        throw std::invalid_argument(what + ": range " + describe(r) + " outside the block");
  if (r.begin == r.end)
    throw std::invalid_argument(what + ": range " + describe(r) + " has a single node");
  Face face;
  if (r.begin[0] == r.end[0]) {
    face.normalAxis = 0;
  } else if (r.begin[1] == r.end[1]) {
    face.normalAxis = 1;
  } else {
    throw std::invalid_argument(what + ": range " + describe(r) + " is not along one index");
  }
  const int fixed = r.begin[face.normalAxis];
  if (fixed != 0 && fixed != size[face.normalAxis] - 1)
    throw std::invalid_argument(what + ": range " + describe(r) + " is not on a block edge");
  face.outward = fixed == 0 ? -1 : 1;
  face.alongAxis = 1 - face.normalAxis;
  const int delta = r.end[face.alongAxis] - r.begin[face.alongAxis];
  face.alongSign = delta > 0 ? 1 : -1;
  face.nodeCount = std::abs(delta) + 1;
  return face;
}

// Index direction d of `own` (0-based) maps to direction |transform[d]| - 1 of `donor`,
// with the sign saying whether the donor index grows with it (CGNS SIDS, Transform).
// Along the face: node k pairs with node k, so the directions agree when both ranges run
// the same way. Across it: stepping out of `own` steps into `donor`, i.e. against the
// donor's outward direction.
std::array<int, 2> transformBetween(const Face& own, const Face& donor) {
  std::array<int, 2> transform{};
  transform[static_cast<std::size_t>(own.alongAxis)] =
      own.alongSign * donor.alongSign * (donor.alongAxis + 1);
  transform[static_cast<std::size_t>(own.normalAxis)] =
      -own.outward * donor.outward * (donor.normalAxis + 1);
  return transform;
}

std::array<int, 2> nodeOf(const NodeRange& r, const Face& face, int k) {
  std::array<int, 2> node = r.begin;
  node[static_cast<std::size_t>(face.alongAxis)] += face.alongSign * k;
  return node;
}

// The names of the two GridConnectivity1to1_t entries of a connection (zone a, zone b).
std::pair<std::string, std::string> entryNames(const BlockConnection& c) {
  if (c.a.block == c.b.block) return {c.name, c.name + "_reverse"};
  return {c.name, c.name};
}

// The BC_t name of each patch: its name, or name_2, name_3, ... for repeats in one zone.
std::vector<std::string> bcNames(const StructuredMesh& mesh) {
  std::map<std::pair<int, std::string>, int> seen;
  std::vector<std::string> names;
  for (const BoundaryPatch& p : mesh.patches) {
    const int count = ++seen[{p.range.block, p.name}];
    names.push_back(count == 1 ? p.name : p.name + "_" + std::to_string(count));
  }
  return names;
}

double meshSize(const StructuredMesh& mesh) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo[2] = {inf, inf}, hi[2] = {-inf, -inf};
  for (const StructuredBlock& b : mesh.blocks)
    for (std::size_t n = 0; n < b.x.size(); ++n) {
      lo[0] = std::min(lo[0], b.x[n]), hi[0] = std::max(hi[0], b.x[n]);
      lo[1] = std::min(lo[1], b.y[n]), hi[1] = std::max(hi[1], b.y[n]);
    }
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

void validateBlocks(const StructuredMesh& mesh) {
  if (mesh.blocks.empty()) throw std::invalid_argument("structured mesh: no blocks");
  std::set<std::string> names;
  for (const StructuredBlock& b : mesh.blocks) {
    checkName(b.name, "block");
    if (!names.insert(b.name).second)
      throw std::invalid_argument("block '" + b.name + "': duplicate block name");
    if (b.ni < 2 || b.nj < 2)
      throw std::invalid_argument("block '" + b.name + "': needs at least 2 x 2 nodes");
    const auto count = static_cast<std::size_t>(b.ni) * static_cast<std::size_t>(b.nj);
    if (b.x.size() != count || b.y.size() != count)
      throw std::invalid_argument("block '" + b.name + "': coordinate arrays are not ni * nj");
    for (int j = 0; j < b.nj; ++j)
      for (int i = 0; i < b.ni; ++i)
        if (!std::isfinite(b.xAt(i, j)) || !std::isfinite(b.yAt(i, j)))
          throw std::invalid_argument("block '" + b.name + "': non-finite coordinate at node (" +
                                      std::to_string(i) + "," + std::to_string(j) + ")");
  }
}

void validateConnection(const StructuredMesh& mesh, const BlockConnection& c, double tolerance) {
  const std::string what = "connection '" + c.name + "'";
  checkName(c.name, what);
  const Face fa = faceOf(mesh, c.a, what + " side a");
  const Face fb = faceOf(mesh, c.b, what + " side b");
  if (fa.nodeCount != fb.nodeCount)
    throw std::invalid_argument(what + ": side a has " + std::to_string(fa.nodeCount) +
                                " nodes, side b " + std::to_string(fb.nodeCount));
  if (!c.translation.allFinite()) throw std::invalid_argument(what + ": non-finite translation");
  if (!c.periodic && !c.translation.isZero(0.0))
    throw std::invalid_argument(what + ": translation given but the connection is not periodic");
  const StructuredBlock& ba = mesh.blocks[static_cast<std::size_t>(c.a.block)];
  const StructuredBlock& bb = mesh.blocks[static_cast<std::size_t>(c.b.block)];
  for (int k = 0; k < fa.nodeCount; ++k) {
    const auto na = nodeOf(c.a, fa, k), nb = nodeOf(c.b, fb, k);
    const double dx = ba.xAt(na[0], na[1]) + c.translation.x() - bb.xAt(nb[0], nb[1]);
    const double dy = ba.yAt(na[0], na[1]) + c.translation.y() - bb.yAt(nb[0], nb[1]);
    if (std::hypot(dx, dy) > tolerance)
      throw std::invalid_argument(what + ": node " + std::to_string(k) +
                                  " of side a does not coincide with node " + std::to_string(k) +
                                  " of side b");
  }
  checkName(entryNames(c).second, what + " entry");
}

// --- writing ---

// Units on the base, and on each coordinate array its class and [length]^1, so that
// readers (and cgnscheck) can tell the coordinates are in metres.
void writeBase(CgnsOutputFile& f, int& base) {
  f.check(cg_base_write(f.fn(), "Base", 2, 2, &base), "base");
  f.check(cg_goto(f.fn(), base, "end"), "goto base");
  f.check(cg_dataclass_write(CGNS_ENUMV(Dimensional)), "base DataClass");
  f.check(cg_units_write(CGNS_ENUMV(Kilogram), CGNS_ENUMV(Meter), CGNS_ENUMV(Second),
                         CGNS_ENUMV(Kelvin), CGNS_ENUMV(Degree)),
          "base units");
}

void writeZone(CgnsOutputFile& f, int base, const StructuredBlock& b) {
  const cgsize_t size[6] = {b.ni, b.nj, b.ni - 1, b.nj - 1, 0, 0};
  int zone = 0;
  f.check(cg_zone_write(f.fn(), base, b.name.c_str(), size, CGNS_ENUMV(Structured), &zone),
          "zone " + b.name);
  const std::pair<const char*, const std::vector<double>*> coordinates[2] = {{"CoordinateX", &b.x},
                                                                             {"CoordinateY", &b.y}};
  for (const auto& [name, values] : coordinates) {
    int index = 0;
    f.check(
        cg_coord_write(f.fn(), base, zone, CGNS_ENUMV(RealDouble), name, values->data(), &index),
        std::string(name) + " of " + b.name);
    f.check(
        cg_goto(f.fn(), base, "Zone_t", zone, "GridCoordinates_t", 1, "DataArray_t", index, "end"),
        "goto coordinate");
    const double lengthExponent[5] = {0, 1, 0, 0, 0};  // mass, length, time, temperature, angle
    f.check(cg_dataclass_write(CGNS_ENUMV(Dimensional)), "coordinate DataClass");
    f.check(cg_exponents_write(CGNS_ENUMV(RealDouble), lengthExponent), "coordinate exponents");
  }
}

CGNS_ENUMT(BCType_t) bcTypeOf(PatchType type) {
  switch (type) {
    case PatchType::wall:
      return CGNS_ENUMV(BCWall);
    case PatchType::inlet:
      return CGNS_ENUMV(BCInflow);
    case PatchType::outlet:
      return CGNS_ENUMV(BCOutflow);
  }
  throw std::invalid_argument("unknown patch type");
}

void writeFamilies(CgnsOutputFile& f, int base, const StructuredMesh& mesh) {
  std::set<std::string> written;
  for (const BoundaryPatch& p : mesh.patches) {
    if (!written.insert(p.name).second) continue;
    int family = 0, familyBc = 0;
    f.check(cg_family_write(f.fn(), base, p.name.c_str(), &family), "family " + p.name);
    f.check(cg_fambc_write(f.fn(), base, family, "FamBC", bcTypeOf(p.type), &familyBc),
            "FamilyBC of " + p.name);
  }
}

void writePatches(CgnsOutputFile& f, int base, const StructuredMesh& mesh) {
  const std::vector<std::string> names = bcNames(mesh);
  for (std::size_t n = 0; n < mesh.patches.size(); ++n) {
    const BoundaryPatch& p = mesh.patches[n];
    const int zone = p.range.block + 1;
    const cgsize_t range[4] = {std::min(p.range.begin[0], p.range.end[0]) + 1,
                               std::min(p.range.begin[1], p.range.end[1]) + 1,
                               std::max(p.range.begin[0], p.range.end[0]) + 1,
                               std::max(p.range.begin[1], p.range.end[1]) + 1};
    int bc = 0;
    f.check(cg_boco_write(f.fn(), base, zone, names[n].c_str(), bcTypeOf(p.type),
                          CGNS_ENUMV(PointRange), 2, range, &bc),
            "BC " + names[n]);
    f.check(cg_goto(f.fn(), base, "Zone_t", zone, "ZoneBC_t", 1, "BC_t", bc, "end"), "goto BC");
    f.check(cg_famname_write(p.name.c_str()), "FamilyName of BC " + names[n]);
  }
}

// cgnscheck warns about arrays without dimensional exponents, and Periodic_t's arrays
// (two lengths and an angle) do not get them from cg_1to1_periodic_write.
void writePeriodicExponents(CgnsOutputFile& f, int base, int zone, int index, const std::string& name) {
  for (const char* array : {"RotationCenter", "RotationAngle", "Translation"}) {
    const bool isAngle = std::string(array) == "RotationAngle";
    const float exponents[5] = {0, isAngle ? 0.0f : 1.0f, 0, 0, isAngle ? 1.0f : 0.0f};
    // cg_goto takes a node name where the index is 0.
    f.check(
        cg_goto(f.fn(), base, "Zone_t", zone, "ZoneGridConnectivity_t", 1, "GridConnectivity1to1_t",
                index, "GridConnectivityProperty_t", 1, "Periodic_t", 1, array, 0, "end"),
        std::string("goto ") + array + " of " + name);
    f.check(cg_dataclass_write(CGNS_ENUMV(Dimensional)), "periodic DataClass of " + name);
    f.check(cg_exponents_write(CGNS_ENUMV(RealSingle), exponents), "periodic exponents of " + name);
  }
}

// One GridConnectivity1to1_t in `own`'s zone. The own range is made ascending (swapping
// both ends of both ranges keeps node k paired with node k).
void writeOneToOne(CgnsOutputFile& f, int base, const StructuredMesh& mesh, const std::string& name,
                   NodeRange own, NodeRange donor, bool periodic,
                   const Eigen::Vector2d& translation) {
  Face ownFace = faceOf(mesh, own, name);
  Face donorFace = faceOf(mesh, donor, name);
  if (ownFace.alongSign < 0) {
    std::swap(own.begin, own.end);
    std::swap(donor.begin, donor.end);
    ownFace.alongSign = 1;
    donorFace.alongSign = -donorFace.alongSign;
  }
  const std::array<int, 2> transform = transformBetween(ownFace, donorFace);
  const cgsize_t range[4] = {own.begin[0] + 1, own.begin[1] + 1, own.end[0] + 1, own.end[1] + 1};
  const cgsize_t donorRange[4] = {donor.begin[0] + 1, donor.begin[1] + 1, donor.end[0] + 1,
                                  donor.end[1] + 1};
  const std::string& donorName = mesh.blocks[static_cast<std::size_t>(donor.block)].name;
  int index = 0;
  f.check(cg_1to1_write(f.fn(), base, own.block + 1, name.c_str(), donorName.c_str(), range,
                        donorRange, transform.data(), &index),
          "1to1 connection " + name);
  if (!periodic) return;
  // The mid-level library stores periodic data as RealSingle only.
  const float centre[2] = {0.0f, 0.0f}, angle[2] = {0.0f, 0.0f};
  const float shift[2] = {static_cast<float>(translation.x()), static_cast<float>(translation.y())};
  f.check(cg_1to1_periodic_write(f.fn(), base, own.block + 1, index, centre, angle, shift),
          "periodic data of " + name);
  writePeriodicExponents(f, base, own.block + 1, index, name);
}

void writeContent(CgnsOutputFile& f, const StructuredMesh& mesh) {
  int base = 0;
  writeBase(f, base);
  for (const StructuredBlock& b : mesh.blocks) writeZone(f, base, b);
  writeFamilies(f, base, mesh);
  writePatches(f, base, mesh);
  for (const BlockConnection& c : mesh.connections) {
    const auto [nameA, nameB] = entryNames(c);
    writeOneToOne(f, base, mesh, nameA, c.a, c.b, c.periodic, c.translation);
    writeOneToOne(f, base, mesh, nameB, c.b, c.a, c.periodic, -c.translation);
  }
  f.close();
}

}  // namespace

void validateStructuredMesh(const StructuredMesh& mesh) {
  validateBlocks(mesh);
  std::map<std::string, PatchType> familyTypes;
  for (const BoundaryPatch& p : mesh.patches) {
    const std::string what = "patch '" + p.name + "'";
    checkName(p.name, what);
    faceOf(mesh, p.range, what);
    const auto [it, inserted] = familyTypes.emplace(p.name, p.type);
    if (!inserted && it->second != p.type)
      throw std::invalid_argument(what + ": patches of one name must have one type");
  }
  // BC and connection names must be unique within a zone (CGNS child names).
  std::set<std::pair<int, std::string>> bcs, connections;
  const std::vector<std::string> names = bcNames(mesh);
  for (std::size_t n = 0; n < names.size(); ++n) {
    checkName(names[n], "patch '" + mesh.patches[n].name + "' BC");
    if (!bcs.insert({mesh.patches[n].range.block, names[n]}).second)
      throw std::invalid_argument("BC name '" + names[n] + "' used twice in one block");
  }
  const double tolerance = 1e-6 * meshSize(mesh);
  for (const BlockConnection& c : mesh.connections) {
    validateConnection(mesh, c, tolerance);
    const auto [nameA, nameB] = entryNames(c);
    if (!connections.insert({c.a.block, nameA}).second ||
        !connections.insert({c.b.block, nameB}).second)
      throw std::invalid_argument("connection name '" + c.name + "' used twice in one block");
  }
}

FileWriter cgnsFileWriter(const StructuredMesh& mesh, const std::filesystem::path& file) {
  validateStructuredMesh(mesh);
  return {file, [&mesh, label = file.string()](const std::filesystem::path& temporary) {
            CgnsOutputFile f(temporary, label);
            writeContent(f, mesh);
          }};
}

void writeCgns(const StructuredMesh& mesh, const std::filesystem::path& file) {
  writeFilesAtomically({cgnsFileWriter(mesh, file)});
}

}  // namespace passageMesh
