#include "passageMesh/quality/MeshQualityReport.hpp"

#include <tinyxml2.h>

#include <cstdio>
#include <stdexcept>

#include "passageMesh/core/InputError.hpp"
#include "passageMesh/structured/CgnsReader.hpp"

#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {
namespace {

const std::string& blockName(const StructuredMesh& mesh, int block) {
  static const std::string none = "none";
  return block < 0 ? none : mesh.blocks[static_cast<std::size_t>(block)].name;
}

void printValue(tinyxml2::XMLPrinter& p, const char* name, double value) {
  p.OpenElement(name);
  p.PushText(formatExact(value).c_str());
  p.CloseElement();
}

void printCell(tinyxml2::XMLPrinter& p, const StructuredMesh& mesh, const char* name,
               const CellLocation& c) {
  p.OpenElement(name);
  p.PushAttribute("block", blockName(mesh, c.block).c_str());
  p.PushAttribute("i", c.i);
  p.PushAttribute("j", c.j);
  p.PushAttribute("x", formatExact(c.x).c_str());
  p.PushAttribute("y", formatExact(c.y).c_str());
  p.CloseElement();
}

void printStatistics(tinyxml2::XMLPrinter& p, const StructuredMesh& mesh,
                     const QualityStatistics& s) {
  printValue(p, "QJmin", s.QJmin);
  printValue(p, "QJavg", s.QJavg);
  printValue(p, "QSmin", s.QSmin);
  printValue(p, "QSavg", s.QSavg);
  printCell(p, mesh, "worstQJ", s.worstQJ);
  printCell(p, mesh, "worstQS", s.worstQS);
}

std::string format(const char* pattern, auto... values) {
  char line[512];
  std::snprintf(line, sizeof line, pattern, values...);
  return line;
}

std::string describeCell(const StructuredMesh& mesh, const CellLocation& c) {
  return format("%s cell (%d, %d) at (%.6g, %.6g) m", blockName(mesh, c.block).c_str(), c.i, c.j,
                c.x, c.y);
}

std::string statisticsLine(const QualityStatistics& s) {
  return format("Q_J min %.4f mean %.4f   Q_S min %.4f mean %.4f", s.QJmin, s.QJavg, s.QSmin,
                s.QSavg);
}

}  // namespace

std::string formatMeshQualityXml(const StructuredMesh& mesh, const MeshQuality& q,
                                 const std::string& source) {
  tinyxml2::XMLPrinter p;
  p.PushHeader(false, true);
  p.PushComment(" passageMesh checkMeshQuality: a-priori quality of the O-block (docs/quality.md) ");
  p.OpenElement("meshQuality");
  p.PushAttribute("source", source.c_str());
  p.PushAttribute("valid", q.valid ? "true" : "false");
  printValue(p, "Q", q.Q);
  printStatistics(p, mesh, q);
  if (!q.valid) {
    p.OpenElement("problem");
    p.PushText(q.problem.c_str());
    p.CloseElement();
  }
  if (!q.blocks.empty()) {
    p.OpenElement("blocks");
    for (std::size_t b = 0; b < q.blocks.size(); ++b) {
      p.OpenElement("block");
      p.PushAttribute("name", mesh.blocks[b].name.c_str());
      printStatistics(p, mesh, q.blocks[b]);
      p.CloseElement();
    }
    p.CloseElement();
  }
  p.CloseElement();
  return p.CStr();
}

std::string formatMeshQualitySummary(const StructuredMesh& mesh, const MeshQuality& q) {
  std::string s;
  if (q.valid) {
    s += format("  Q = %.6f (valid)   O-block: %s\n", q.Q, statisticsLine(q).c_str());
  } else {
    s += "  *** INVALID MESH: " + q.problem + " ***\n";
    s += format("  Q = %g (the invalid-mesh value)   O-block: %s\n", q.Q, statisticsLine(q).c_str());
  }
  s += "  worst Q_J: " + describeCell(mesh, q.worstQJ) + format(", Q_J = %.4f\n", q.QJmin);
  s += "  worst Q_S: " + describeCell(mesh, q.worstQS) + format(", Q_S = %.4f\n", q.QSmin);
  for (std::size_t b = 0; b < q.blocks.size(); ++b) {
    const StructuredBlock& block = mesh.blocks[b];
    s += format("  %-8s %4d x %-4d nodes  %s\n", block.name.c_str(), block.ni, block.nj,
                statisticsLine(q.blocks[b]).c_str());
  }
  return s;
}

MeshWithQuality readMeshWithQuality(const std::filesystem::path& cgnsFile) {
  MeshWithQuality result{readCgns(cgnsFile), {}};
  try {
    result.quality = computeMeshQuality(result.mesh, {.everyBlock = true});
  } catch (const std::invalid_argument& e) {
    throw InputError(cgnsFile.string(), 0, e.what());
  }
  return result;
}

}  // namespace passageMesh
