#include "passageMesh/meshExport/Su2Cgns.hpp"

#include <cgnslib.h>

#include <set>
#include <sstream>
#include <vector>

#include "passageMesh/core/NumberFormat.hpp"
#include "passageMesh/structured/CgnsLibrary.hpp"

namespace passageMesh {

namespace {

// The periodic pair as the CGNS standard describes it (SU2 itself reads the config): a
// 1-to-1 abutting connection from the periodicLower nodes to the periodicUpper nodes of
// the same zone, with the translation lower -> upper as its periodic property.
void writePeriodicConnection(const CgnsOutputFile& f, int base, int zone, const UnstructuredPassage& passage) {
  const EdgePatch* lower = nullptr;
  const EdgePatch* upper = nullptr;
  for (const EdgePatch& p : passage.patches) {
    if (p.kind == EdgePatchKind::periodicLower) lower = &p;
    if (p.kind == EdgePatchKind::periodicUpper) upper = &p;
  }
  if (!lower || !upper || lower->edges.size() != upper->edges.size()) return;
  std::vector<cgsize_t> points, donors;
  std::set<int> seen;
  const auto pair = [&](int p, int d) {
    if (seen.insert(p).second) {
      points.push_back(p + 1);
      donors.push_back(d + 1);
    }
  };
  // Edge k of the upper patch is edge k of the lower one translated, perhaps the other
  // way round: each lower node goes with the upper end point nearer its image.
  for (std::size_t k = 0; k < lower->edges.size(); ++k) {
    const MeshEdge& l = lower->edges[k];
    const MeshEdge& u = upper->edges[k];
    const Eigen::Vector2d image = passage.points[static_cast<std::size_t>(l.p0)] + passage.translation;
    const bool same = (passage.points[static_cast<std::size_t>(u.p0)] - image).norm() <=
                      (passage.points[static_cast<std::size_t>(u.p1)] - image).norm();
    pair(l.p0, same ? u.p0 : u.p1);
    pair(l.p1, same ? u.p1 : u.p0);
  }
  int connection = 0;
  f.check(cg_conn_write(f.fn(), base, zone, "periodic", CGNS_ENUMV(Vertex), CGNS_ENUMV(Abutting1to1),
                        CGNS_ENUMV(PointList), static_cast<cgsize_t>(points.size()), points.data(), "passage",
                        CGNS_ENUMV(Unstructured), CGNS_ENUMV(PointListDonor), CGNS_ENUMV(Integer),
                        static_cast<cgsize_t>(donors.size()), donors.data(), &connection),
          "periodic connection");
  const float centre[2] = {0, 0}, angle[2] = {0, 0};
  const float translation[2] = {static_cast<float>(passage.translation.x()),
                                static_cast<float>(passage.translation.y())};
  f.check(cg_conn_periodic_write(f.fn(), base, zone, connection, centre, angle, translation),
          "periodic translation");
  // Units of RotationCenter, RotationAngle, Translation: metre, degree, metre.
  const double exponents[3][5] = {{0, 1, 0, 0, 0}, {0, 0, 0, 0, 1}, {0, 1, 0, 0, 0}};
  for (int k = 0; k < 3; ++k) {
    f.check(cg_goto(f.fn(), base, "Zone_t", zone, "ZoneGridConnectivity_t", 1, "GridConnectivity_t", connection,
                    "GridConnectivityProperty_t", 1, "Periodic_t", 1, "DataArray_t", k + 1, "end"),
            "goto periodic data");
    f.check(cg_exponents_write(CGNS_ENUMV(RealDouble), exponents[k]), "periodic exponents");
  }
}

// The whole file (base, units, the zone with its sections and the periodic connection)
// written to `file`; errors name `label` (the target of the temporary being written).
void writeSu2File(const UnstructuredPassage& passage, const std::filesystem::path& file,
                  const std::string& label) {
  CgnsOutputFile f(file, label);
  int base = 0, zone = 0, coordinate = 0, section = 0;
  f.check(cg_base_write(f.fn(), "Base", 2, 2, &base), "base");
  f.check(cg_goto(f.fn(), base, "end"), "goto base");
  f.check(cg_dataclass_write(CGNS_ENUMV(Dimensional)), "DataClass");
  f.check(cg_units_write(CGNS_ENUMV(Kilogram), CGNS_ENUMV(Meter), CGNS_ENUMV(Second), CGNS_ENUMV(Kelvin),
                         CGNS_ENUMV(Degree)), "units");
  cgsize_t size[3] = {static_cast<cgsize_t>(passage.points.size()), static_cast<cgsize_t>(passage.cells.size()), 0};
  f.check(cg_zone_write(f.fn(), base, "passage", size, CGNS_ENUMV(Unstructured), &zone), "zone");
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<double> values;
    for (const auto& p : passage.points) values.push_back(p[axis]);
    const char* name = axis == 0 ? "CoordinateX" : "CoordinateY";
    f.check(cg_coord_write(f.fn(), base, zone, CGNS_ENUMV(RealDouble), name, values.data(), &coordinate), name);
    f.check(cg_goto(f.fn(), base, "Zone_t", zone, "GridCoordinates_t", 1, "DataArray_t", coordinate, "end"),
            "goto coordinate");
    const double lengthExponent[5] = {0, 1, 0, 0, 0};
    f.check(cg_exponents_write(CGNS_ENUMV(RealDouble), lengthExponent), "exponents");
  }
  std::vector<cgsize_t> quads;
  for (const auto& c : passage.cells)
    for (const int p : c) quads.push_back(p + 1);  // CGNS numbers from 1
  cgsize_t last = static_cast<cgsize_t>(passage.cells.size());
  f.check(cg_section_write(f.fn(), base, zone, "cells", CGNS_ENUMV(QUAD_4), 1, last, 0, quads.data(), &section),
          "section cells");
  for (const EdgePatch& p : passage.patches) {
    std::vector<cgsize_t> bars;
    for (const MeshEdge& e : p.edges) {
      bars.push_back(e.p0 + 1);
      bars.push_back(e.p1 + 1);
    }
    const cgsize_t first = last + 1;
    last += static_cast<cgsize_t>(p.edges.size());
    f.check(cg_section_write(f.fn(), base, zone, p.name.c_str(), CGNS_ENUMV(BAR_2), first, last, 0, bars.data(),
                             &section), "section " + p.name);
  }
  writePeriodicConnection(f, base, zone, passage);
  f.close();
}

}  // namespace

FileWriter su2CgnsFileWriter(const UnstructuredPassage& passage, const std::filesystem::path& file) {
  return {file, [&passage, label = file.string()](const std::filesystem::path& temporary) {
            writeSu2File(passage, temporary, label);
          }};
}

void writeSu2Cgns(const UnstructuredPassage& passage, const std::filesystem::path& file) {
  writeFilesAtomically({su2CgnsFileWriter(passage, file)});
}

std::string su2ConfigFragment(const UnstructuredPassage& passage, const std::string& meshFileName) {
  std::ostringstream out;
  const Eigen::Vector2d& t = passage.translation;
  out << "% passageMesh exportMesh: mesh and markers of " << meshFileName << "\n"
      << "MESH_FILENAME= " << meshFileName << "\nMESH_FORMAT= CGNS\n"
      << "% periodic pair: translation from periodicLower to periodicUpper [m]\n"
      << "MARKER_PERIODIC= ( periodicLower, periodicUpper, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, "
      << formatExact(t.x()) << ", " << formatExact(t.y()) << ", 0.0 )\n"
      << "% adiabatic blade wall\n";
  for (const EdgePatch& p : passage.patches)
    if (p.kind == EdgePatchKind::wall) out << "MARKER_HEATFLUX= ( " << p.name << ", 0.0 )\n";
  out << "% complete with the flow conditions, e.g.\n"
      << "% MARKER_INLET= ( inlet, T0, P0, dirX, dirY, 0.0 )\n"
      << "% MARKER_OUTLET= ( outlet, P )\n";
  return out.str();
}

}  // namespace passageMesh
