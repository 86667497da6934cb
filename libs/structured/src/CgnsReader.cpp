#include "passageMesh/structured/CgnsReader.hpp"

#include <cgns_io.h>
#include <cgnslib.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "passageMesh/core/InputError.hpp"
#include "passageMesh/structured/CgnsLibrary.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"

namespace passageMesh {
namespace {

using CgnsName = char[33];  // CGNS names: at most 32 characters

class CgnsInput {
 public:
  explicit CgnsInput(const std::filesystem::path& path) : file_(path.string()) {
    if (!std::filesystem::exists(path)) throw InputError(file_, 0, "file not found");
    prepareCgnsLibrary();  // (cg_is_cgns starts HDF5 too)
    int type = 0;
    if (cg_is_cgns(file_.c_str(), &type) != CG_OK)
      throw InputError(file_, 0, "not a CGNS file (expected a mesh written by writeCgns)");
    check(cg_open(file_.c_str(), CG_MODE_READ, &fn_), "cannot open");
  }
  ~CgnsInput() { cg_close(fn_); }
  CgnsInput(const CgnsInput&) = delete;
  CgnsInput& operator=(const CgnsInput&) = delete;

  void check(int status, const std::string& what) const {
    if (status != CG_OK) fail(what + " (CGNS: " + cg_get_error() + ")");
  }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, 0, what); }
  int fn() const { return fn_; }

 private:
  std::string file_;
  int fn_ = -1;
};

// A GridConnectivity1to1_t entry: donor = own + translation, node for node.
struct OneToOneEntry {
  std::string name;
  NodeRange own, donor;
  bool periodic = false;
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();
  bool used = false;
};

NodeRange rangeOf(int block, const cgsize_t* r) {
  return {block,
          {static_cast<int>(r[0]) - 1, static_cast<int>(r[1]) - 1},
          {static_cast<int>(r[2]) - 1, static_cast<int>(r[3]) - 1}};
}

int blockNamed(const CgnsInput& in, const StructuredMesh& mesh, const std::string& name) {
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    if (mesh.blocks[b].name == name) return static_cast<int>(b);
  in.fail("connection to unknown zone '" + name + "'");
}

// The zone names in the order they were written. The mid-level library lists zones sorted
// by name; the HDF5 file keeps the creation order, which is the block order. Empty when
// the low-level listing fails (then the library's order is used).
std::vector<std::string> zonesInWriteOrder(const CgnsInput& in, const std::string& baseName) {
  int cgio = 0;
  double root = 0, base = 0;
  int children = 0;
  if (cg_get_cgio(in.fn(), &cgio) != CG_OK || cg_root_id(in.fn(), &root) != CG_OK ||
      cgio_get_node_id(cgio, root, baseName.c_str(), &base) != 0 ||
      cgio_number_children(cgio, base, &children) != 0 || children < 1)
    return {};
  std::vector<double> ids(static_cast<std::size_t>(children));
  int listed = 0;
  if (cgio_children_ids(cgio, base, 1, children, &listed, ids.data()) != 0) return {};
  std::vector<std::string> zones;
  for (int n = 0; n < listed; ++n) {
    char label[CGIO_MAX_LABEL_LENGTH + 1] = {}, name[CGIO_MAX_NAME_LENGTH + 1] = {};
    if (cgio_get_label(cgio, ids[static_cast<std::size_t>(n)], label) != 0 ||
        cgio_get_name(cgio, ids[static_cast<std::size_t>(n)], name) != 0)
      return {};
    if (std::string(label) == "Zone_t") zones.emplace_back(name);
  }
  return zones;
}

// Reads every zone; returns the block index of each zone (zone z is blockOfZone[z - 1]).
std::vector<int> readZones(const CgnsInput& in, const std::string& baseName,
                           StructuredMesh& mesh) {
  int zones = 0;
  in.check(cg_nzones(in.fn(), 1, &zones), "cannot count the zones");
  if (zones < 1) in.fail("no zones (expected one structured zone per block)");
  std::vector<StructuredBlock> read;
  for (int z = 1; z <= zones; ++z) {
    CGNS_ENUMT(ZoneType_t) type;
    in.check(cg_zone_type(in.fn(), 1, z, &type), "zone type");
    CgnsName name{};
    cgsize_t size[9] = {};
    in.check(cg_zone_read(in.fn(), 1, z, name, size), "zone " + std::to_string(z));
    if (type != CGNS_ENUMV(Structured))
      in.fail("zone '" + std::string(name) + "' is not structured");
    StructuredBlock b;
    b.name = name;
    b.ni = static_cast<int>(size[0]);
    b.nj = static_cast<int>(size[1]);
    if (b.ni < 2 || b.nj < 2) in.fail("zone '" + b.name + "' has fewer than 2 x 2 nodes");
    const auto count = static_cast<std::size_t>(b.ni) * static_cast<std::size_t>(b.nj);
    b.x.resize(count);
    b.y.resize(count);
    const cgsize_t first[2] = {1, 1}, last[2] = {size[0], size[1]};
    for (auto [axis, values] : {std::pair{"CoordinateX", &b.x}, std::pair{"CoordinateY", &b.y}})
      in.check(cg_coord_read(in.fn(), 1, z, axis, CGNS_ENUMV(RealDouble), first, last,
                             values->data()),
               "zone '" + b.name + "': expected " + axis);
    read.push_back(std::move(b));
  }
  std::vector<std::string> order = zonesInWriteOrder(in, baseName);
  std::vector<int> blockOfZone(read.size());
  for (std::size_t z = 0; z < read.size(); ++z) {
    const auto at = std::find(order.begin(), order.end(), read[z].name);
    if (order.size() != read.size() || at == order.end()) {  // fall back to the library's order
      for (std::size_t k = 0; k < read.size(); ++k) blockOfZone[k] = static_cast<int>(k);
      break;
    }
    blockOfZone[z] = static_cast<int>(at - order.begin());
  }
  mesh.blocks.resize(read.size());
  for (std::size_t z = 0; z < read.size(); ++z)
    mesh.blocks[static_cast<std::size_t>(blockOfZone[z])] = std::move(read[z]);
  return blockOfZone;
}

PatchType patchTypeOf(const CgnsInput& in, CGNS_ENUMT(BCType_t) type, const std::string& what) {
  switch (type) {
    case CGNS_ENUMV(BCWall):
    case CGNS_ENUMV(BCWallViscous):
    case CGNS_ENUMV(BCWallViscousHeatFlux):
    case CGNS_ENUMV(BCWallViscousIsothermal):
    case CGNS_ENUMV(BCWallInviscid):
      return PatchType::wall;
    case CGNS_ENUMV(BCInflow):
    case CGNS_ENUMV(BCInflowSubsonic):
    case CGNS_ENUMV(BCInflowSupersonic):
      return PatchType::inlet;
    case CGNS_ENUMV(BCOutflow):
    case CGNS_ENUMV(BCOutflowSubsonic):
    case CGNS_ENUMV(BCOutflowSupersonic):
      return PatchType::outlet;
    default:
      in.fail(what + ": BC type " + BCTypeName[type] + " (expected a wall, inflow or outflow)");
  }
}

// The FamilyBC type of family `name` of the base.
CGNS_ENUMT(BCType_t) familyBcType(const CgnsInput& in, const std::string& name) {
  int families = 0;
  in.check(cg_nfamilies(in.fn(), 1, &families), "families");
  for (int f = 1; f <= families; ++f) {
    CgnsName familyName{};
    int bcs = 0, geometries = 0;
    in.check(cg_family_read(in.fn(), 1, f, familyName, &bcs, &geometries), "family");
    if (name != familyName || bcs < 1) continue;
    CgnsName bcName{};
    CGNS_ENUMT(BCType_t) type;
    in.check(cg_fambc_read(in.fn(), 1, f, 1, bcName, &type), "FamilyBC of " + name);
    return type;
  }
  in.fail("family '" + name + "' has no FamilyBC");
}

void readPatches(const CgnsInput& in, int z, int block, StructuredMesh& mesh) {
  int bcs = 0;
  in.check(cg_nbocos(in.fn(), 1, z, &bcs), "BCs");
  for (int bc = 1; bc <= bcs; ++bc) {
    CgnsName name{};
    CGNS_ENUMT(BCType_t) type;
    CGNS_ENUMT(PointSetType_t) pointSet;
    cgsize_t points = 0, normalSize = 0;
    int normalIndex[3] = {}, datasets = 0;
    CGNS_ENUMT(DataType_t) normalType;
    in.check(cg_boco_info(in.fn(), 1, z, bc, name, &type, &pointSet, &points, normalIndex,
                          &normalSize, &normalType, &datasets),
             "BC " + std::to_string(bc));
    const std::string what = "BC '" + std::string(name) + "' of zone '" + mesh.blocks[static_cast<std::size_t>(block)].name + "'";
    if (pointSet != CGNS_ENUMV(PointRange) || points != 2) in.fail(what + ": expected a PointRange");
    cgsize_t range[4] = {};
    in.check(cg_boco_read(in.fn(), 1, z, bc, range, nullptr), what);
    BoundaryPatch patch;
    patch.name = name;
    patch.range = rangeOf(block, range);
    in.check(cg_goto(in.fn(), 1, "Zone_t", z, "ZoneBC_t", 1, "BC_t", bc, "end"), what);
    CgnsName family{};
    const int status = cg_famname_read(family);
    if (status == CG_OK) {
      patch.name = family;
    } else if (status != CG_NODE_NOT_FOUND) {
      in.check(status, what + ": FamilyName");
    }
    if (type == CGNS_ENUMV(FamilySpecified)) type = familyBcType(in, patch.name);
    patch.type = patchTypeOf(in, type, what);
    mesh.patches.push_back(std::move(patch));
  }
}

void readOneToOnes(const CgnsInput& in, int z, int block, const StructuredMesh& mesh,
                   std::vector<OneToOneEntry>& entries) {
  int count = 0;
  in.check(cg_n1to1(in.fn(), 1, z, &count), "1to1 connections");
  for (int n = 1; n <= count; ++n) {
    CgnsName name{}, donorName{};
    cgsize_t range[4] = {}, donorRange[4] = {};
    int transform[3] = {};
    in.check(cg_1to1_read(in.fn(), 1, z, n, name, donorName, range, donorRange, transform),
             "1to1 connection " + std::to_string(n));
    OneToOneEntry e;
    e.name = name;
    e.own = rangeOf(block, range);
    e.donor = rangeOf(blockNamed(in, mesh, donorName), donorRange);
    float centre[3] = {}, angle[3] = {}, translation[3] = {};
    const int status = cg_1to1_periodic_read(in.fn(), 1, z, n, centre, angle, translation);
    if (status == CG_OK) {
      if (angle[0] != 0 || angle[1] != 0)
        in.fail("connection '" + e.name + "': rotational periodicity (expected a translation)");
      e.periodic = true;
      e.translation = {translation[0], translation[1]};
    } else if (status != CG_NODE_NOT_FOUND) {
      in.check(status, "periodic data of connection '" + e.name + "'");
    }
    entries.push_back(std::move(e));
  }
}

// p is e's partner: the same node pairs seen from the other side.
bool arePartners(const OneToOneEntry& e, const OneToOneEntry& p) {
  if (p.used || p.own.block != e.donor.block || p.donor.block != e.own.block) return false;
  const bool named = p.name == e.name || p.name == e.name + "_reverse" || e.name == p.name + "_reverse";
  const bool same = p.own.begin == e.donor.begin && p.own.end == e.donor.end &&
                    p.donor.begin == e.own.begin && p.donor.end == e.own.end;
  const bool reversed = p.own.begin == e.donor.end && p.own.end == e.donor.begin &&
                        p.donor.begin == e.own.end && p.donor.end == e.own.begin;
  return named && (same || reversed) && p.periodic == e.periodic;
}

// The translation in double precision from the first node pair, checked against the
// single-precision value stored in the file.
Eigen::Vector2d preciseTranslation(const CgnsInput& in, const StructuredMesh& mesh,
                                   const BlockConnection& c, const Eigen::Vector2d& stored) {
  const StructuredBlock& a = mesh.blocks[static_cast<std::size_t>(c.a.block)];
  const StructuredBlock& b = mesh.blocks[static_cast<std::size_t>(c.b.block)];
  const auto [ia, ja] = c.a.begin;
  const auto [ib, jb] = c.b.begin;
  if (ia < 0 || ia >= a.ni || ja < 0 || ja >= a.nj || ib < 0 || ib >= b.ni || jb < 0 || jb >= b.nj)
    in.fail("connection '" + c.name + "': range outside its zone");
  const Eigen::Vector2d t(b.xAt(ib, jb) - a.xAt(ia, ja), b.yAt(ib, jb) - a.yAt(ia, ja));
  if ((t - stored).norm() > 1e-6 * stored.norm())
    in.fail("connection '" + c.name + "': the periodic translation does not match the nodes");
  return t;
}

void pairConnections(const CgnsInput& in, std::vector<OneToOneEntry>& entries,
                     StructuredMesh& mesh) {
  for (std::size_t n = 0; n < entries.size(); ++n) {
    if (entries[n].used) continue;
    entries[n].used = true;
    OneToOneEntry* side = &entries[n];
    for (std::size_t m = n + 1; m < entries.size(); ++m) {
      if (!arePartners(entries[n], entries[m])) continue;
      entries[m].used = true;
      if (entries[n].name == entries[m].name + "_reverse") side = &entries[m];
      break;
    }
    BlockConnection c{side->name, side->own, side->donor, side->periodic, Eigen::Vector2d::Zero()};
    if (c.periodic) c.translation = preciseTranslation(in, mesh, c, side->translation);
    mesh.connections.push_back(std::move(c));
  }
}

}  // namespace

StructuredMesh readCgns(const std::filesystem::path& file) {
  CgnsInput in(file);
  int bases = 0;
  in.check(cg_nbases(in.fn(), &bases), "cannot count the bases");
  if (bases < 1) in.fail("no base (expected a CGNS mesh)");
  CgnsName baseName{};
  int cellDimension = 0, physicalDimension = 0;
  in.check(cg_base_read(in.fn(), 1, baseName, &cellDimension, &physicalDimension), "base");
  if (cellDimension != 2 || physicalDimension != 2)
    in.fail("base '" + std::string(baseName) + "' is not 2-D (expected CellDimension = " +
            "PhysicalDimension = 2)");
  StructuredMesh mesh;
  const std::vector<int> blockOfZone = readZones(in, baseName, mesh);
  std::vector<int> zoneOfBlock(blockOfZone.size());
  for (std::size_t z = 0; z < blockOfZone.size(); ++z)
    zoneOfBlock[static_cast<std::size_t>(blockOfZone[z])] = static_cast<int>(z) + 1;
  std::vector<OneToOneEntry> entries;
  for (int b = 0; b < static_cast<int>(mesh.blocks.size()); ++b) {
    readPatches(in, zoneOfBlock[static_cast<std::size_t>(b)], b, mesh);
    readOneToOnes(in, zoneOfBlock[static_cast<std::size_t>(b)], b, mesh, entries);
  }
  pairConnections(in, entries, mesh);
  try {
    validateStructuredMesh(mesh);
  } catch (const std::invalid_argument& e) {
    in.fail(std::string("inconsistent mesh: ") + e.what());
  }
  return mesh;
}

}  // namespace passageMesh
