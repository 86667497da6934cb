#include "passageMesh/plot/MeshPictures.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "passageMesh/core/GnuplotRun.hpp"
#include "passageMesh/core/NumberFormat.hpp"
#include "passageMesh/meshExport/BladeEdges.hpp"
#include "passageMesh/plot/MeshPlotData.hpp"
#include "passageMesh/quality/OBlockNeighbours.hpp"

namespace passageMesh {

namespace {

namespace fs = std::filesystem;

std::string number(double v, const char* format = "%.3g") {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::string pointsData(const std::vector<Eigen::Vector2d>& points) {
  std::ostringstream out;
  for (const auto& p : points) out << formatExact(p.x()) << ' ' << formatExact(p.y()) << '\n';
  return out.str();
}

// Axis settings shared by every picture: metres, equal scales, no key unless asked.
const char* commonSettings =
    "reset\nset size ratio -1\nset xlabel 'x [m]'\nset ylabel 'y [m]'\nunset key\n"
    "set format x '%g'\nset format y '%g'\nset grid front lc rgb '#c0c0c0'\n";

// A square box `width` wide centred on `centre`, as gnuplot ranges.
std::string box(const Eigen::Vector2d& centre, double width) {
  const double h = width / 2;
  return "set xrange [" + formatExact(centre.x() - h) + ":" + formatExact(centre.x() + h) + "]\n"
         "set yrange [" + formatExact(centre.y() - h) + ":" + formatExact(centre.y() + h) + "]\n";
}

std::string qualityTitle(const MeshQuality& q) {
  return "mesh Q = " + number(q.Q, "%.4f") + (q.valid ? "" : " (INVALID MESH)");
}

struct Measure {
  const char* name;      // Q_J or Q_S, gnuplot's enhanced text
  const char* file;
  const std::vector<std::vector<double>>* cells;
  double min, mean;
  CellLocation worst;
};

// Cells filled by one measure: the whole O-block (left) and a zoom on its worst cell
// (right, cell edges drawn), the worst cell circled in both.
std::string qualityScript(GnuplotRun& plot, const fs::path& folder, const StructuredMesh& mesh,
                          int oBlock, const Measure& m, const MeshQuality& q, double chord,
                          const std::string& blade, const std::string& gridLines) {
  const StructuredBlock& o = mesh.blocks[static_cast<std::size_t>(oBlock)];
  const std::string cells = plot.dataFile(cellValuesData(o, (*m.cells)[static_cast<std::size_t>(oBlock)]));
  const std::string worst = plot.dataFile(formatExact(m.worst.x) + " " + formatExact(m.worst.y) + "\n");
  const std::string worstText = "worst cell (" + std::to_string(m.worst.i) + ", " +
                                std::to_string(m.worst.j) + "): " + m.name + " = " + number(m.min, "%.4f");
  std::ostringstream s;
  s << gnuplotPngTerminal(1800, 820) << plot.output(folder / m.file)
    << "set multiplot layout 1,2 title '" << m.name << " of the O-block cells: min " << number(m.min, "%.4f")
    << ", mean " << number(m.mean, "%.4f") << "   (" << qualityTitle(q) << ")' font ',14'\n";
  for (int panel = 0; panel < 2; ++panel) {
    s << commonSettings
      << "set palette defined (0 '#7f0000', 0.3 '#ff2000', 0.55 '#ffd000', 0.75 '#a0e060', 1 '#1060c0')\n"
      << "set cbrange [0:1]\nset cblabel '" << m.name << "'\nset key top right opaque\n";
    if (panel == 0) {
      s << "set title 'whole O-block'\nplot " << cells << " using 1:2:3 with filledcurves closed fc palette notitle, ";
    } else {
      s << box({m.worst.x, m.worst.y}, zoomBoxChords * chord)
        << "set title '" << worstText << " (box " << number(zoomBoxChords * 100, "%g") << " % of chord)'\n"
        << "plot " << cells << " using 1:2:3 with filledcurves closed fc palette notitle, "
        << gridLines << " with lines lc rgb '#404040' lw 0.5 notitle, ";
    }
    s << blade << " with lines lc rgb 'black' lw 1.5 notitle, "
      << worst << " with points pt 6 ps 4 lw 3 lc rgb 'magenta' title 'worst cell'\n";
  }
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace

std::vector<fs::path> drawMeshPictures(const StructuredMesh& mesh, const MeshQuality& quality,
                                       const BladeCurves* blade, const fs::path& folder,
                                       const std::string& gnuplot) {
  const int oBlock = findOBlock(mesh);
  if (quality.cellQJ.size() != mesh.blocks.size() || quality.cellQS.size() != mesh.blocks.size())
    throw std::invalid_argument("drawMeshPictures: the quality holds no cell values (everyBlock)");
  const BladeEdges edges = findBladeEdges(mesh);
  GnuplotRun plot(gnuplot);
  const std::string wall = plot.dataFile(nodeRowData(mesh.blocks[static_cast<std::size_t>(oBlock)], 0));
  const std::string everySecond = plot.dataFile(gridLinesData(mesh, 2));
  const std::string everyLine = plot.dataFile(gridLinesData(mesh, 1));
  const std::string lines = " with lines lc rgb '#203870' lw 0.6, ";
  const std::string bladeLine = " with lines lc rgb 'black' lw 2\n";
  std::ostringstream s;
  s << gnuplotPngTerminal(1600, 1000) << plot.output(folder / "passage.png") << commonSettings
    << "set title 'passage mesh, every second grid line (" << qualityTitle(quality) << ")'\n"
    << "plot " << everySecond << lines << wall << bladeLine;
  const struct { const char* file; const char* name; Eigen::Vector2d centre; } zooms[] = {
      {"leadingEdge.png", "leading edge", edges.leadingEdge},
      {"trailingEdge.png", "trailing edge", edges.trailingEdge}};
  for (const auto& z : zooms)
    s << gnuplotPngTerminal(1000, 1000) << plot.output(folder / z.file) << commonSettings
      << box(z.centre, zoomBoxChords * edges.chord) << "set title '" << z.name << ", every grid line (box "
      << number(zoomBoxChords * 100, "%g") << " % of chord " << number(edges.chord, "%.4g") << " m)'\n"
      << "plot " << everyLine << lines << wall << bladeLine;
  const Measure measures[] = {
      {"Q_S", "qualityQS.png", &quality.cellQS, quality.QSmin, quality.QSavg, quality.worstQS},
      {"Q_J", "qualityQJ.png", &quality.cellQJ, quality.QJmin, quality.QJavg, quality.worstQJ}};
  for (const Measure& m : measures) s << qualityScript(plot, folder, mesh, oBlock, m, quality, edges.chord, wall, everyLine);
  std::vector<fs::path> pictures = {folder / "passage.png", folder / "leadingEdge.png",
                                    folder / "trailingEdge.png", folder / "qualityQS.png",
                                    folder / "qualityQJ.png"};
  if (blade) {
    s << gnuplotPngTerminal(1600, 900) << plot.output(folder / "blade.png") << commonSettings
      << "set key below\nset title 'fitted blade profile over the input points'\n"
      << "plot " << plot.dataFile(pointsData(blade->profile))
      << " with lines lc rgb '#1060c0' lw 1.5 title 'fitted profile (bladeProfile.dat)', "
      << plot.dataFile(pointsData(blade->inputPoints))
      << " with points pt 6 ps 1.2 lc rgb '#d02000' title 'input points (bladePoints.dat)'\n";
    pictures.push_back(folder / "blade.png");
  }
  plot.run(s.str());
  return pictures;
}

}  // namespace passageMesh
