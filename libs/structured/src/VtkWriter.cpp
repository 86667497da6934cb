#include "passageMesh/structured/VtkWriter.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {
namespace {

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::size_t cellCount(const StructuredBlock& b) {
  return static_cast<std::size_t>(b.ni - 1) * static_cast<std::size_t>(b.nj - 1);
}

void validateBlock(const StructuredBlock& b) {
  const std::string what = "block '" + b.name + "'";
  // The name becomes a file name inside the block folder.
  if (b.name.empty() || b.name == "." || b.name == ".." ||
      b.name.find_first_of(std::string("/\\\0", 3)) != std::string::npos)
    throw std::invalid_argument(what + ": name is not usable as a file name");
  if (b.ni < 2 || b.nj < 2) throw std::invalid_argument(what + ": needs at least 2 x 2 nodes");
  const auto count = static_cast<std::size_t>(b.ni) * static_cast<std::size_t>(b.nj);
  if (b.x.size() != count || b.y.size() != count)
    throw std::invalid_argument(what + ": coordinate arrays are not ni * nj");
  for (std::size_t n = 0; n < count; ++n)
    if (!std::isfinite(b.x[n]) || !std::isfinite(b.y[n]))
      throw std::invalid_argument(what + ": non-finite coordinate at node index " +
                                  std::to_string(n));
}

void validate(const StructuredMesh& mesh, const std::vector<BlockField>& fields) {
  if (mesh.blocks.empty()) throw std::invalid_argument("structured mesh: no blocks");
  std::set<std::string> blockNames;
  for (const StructuredBlock& b : mesh.blocks) {
    validateBlock(b);
    if (!blockNames.insert(b.name).second)
      throw std::invalid_argument("block '" + b.name + "': duplicate block name");
  }
  std::set<std::string> fieldNames;
  for (const BlockField& field : fields) {
    const std::string what = "cell field '" + field.name + "'";
    if (field.name.empty()) throw std::invalid_argument("cell field: empty name");
    if (!fieldNames.insert(field.name).second)
      throw std::invalid_argument(what + ": duplicate field name");
    if (field.values.size() != mesh.blocks.size())
      throw std::invalid_argument(what + ": needs values for each of the " +
                                  std::to_string(mesh.blocks.size()) + " blocks");
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
      if (field.values[b].size() != cellCount(mesh.blocks[b]))
        throw std::invalid_argument(what + ": block '" + mesh.blocks[b].name + "' has " +
                                    std::to_string(cellCount(mesh.blocks[b])) + " cells but " +
                                    std::to_string(field.values[b].size()) + " values");
      // VTK's ASCII reader does not parse "nan" or "inf".
      for (double v : field.values[b])
        if (!std::isfinite(v))
          throw std::invalid_argument(what + ": non-finite value in block '" + mesh.blocks[b].name +
                                      "'");
    }
  }
}

std::string vtsContent(const StructuredMesh& mesh, std::size_t blockIndex,
                       const std::vector<BlockField>& fields) {
  const StructuredBlock& b = mesh.blocks[blockIndex];
  const std::string extent =
      "0 " + std::to_string(b.ni - 1) + " 0 " + std::to_string(b.nj - 1) + " 0 0";
  std::string s;
  s.reserve(64 * b.x.size() + 32 * cellCount(b) * fields.size() + 1024);
  s += "<?xml version=\"1.0\"?>\n";
  s += "<VTKFile type=\"StructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  s += "  <StructuredGrid WholeExtent=\"" + extent + "\">\n";
  s += "    <Piece Extent=\"" + extent + "\">\n";
  s += "      <CellData>\n";
  for (const BlockField& field : fields) {
    s += "        <DataArray type=\"Float64\" Name=\"" + xmlEscaped(field.name) +
         "\" format=\"ascii\">\n";
    for (double v : field.values[blockIndex]) s += "          " + formatExact(v) + "\n";
    s += "        </DataArray>\n";
  }
  s += "      </CellData>\n";
  s += "      <Points>\n";
  s += "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  // VTK orders structured points with i fastest, as StructuredBlock stores them.
  for (std::size_t n = 0; n < b.x.size(); ++n)
    s += "          " + formatExact(b.x[n]) + " " + formatExact(b.y[n]) + " 0\n";
  s += "        </DataArray>\n";
  s += "      </Points>\n";
  s += "    </Piece>\n";
  s += "  </StructuredGrid>\n";
  s += "</VTKFile>\n";
  return s;
}

}  // namespace

void writeVtm(const StructuredMesh& mesh, const std::filesystem::path& vtmFile,
              const std::vector<BlockField>& cellFields) {
  for (const auto& [file, content] : vtmFileContents(mesh, vtmFile, cellFields))
    writeFileAtomically(file, content);
}

std::vector<std::pair<std::filesystem::path, std::string>> vtmFileContents(
    const StructuredMesh& mesh, const std::filesystem::path& vtmFile,
    const std::vector<BlockField>& cellFields) {
  validate(mesh, cellFields);
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  const std::filesystem::path folderName = vtmFile.stem();
  const std::filesystem::path folder = vtmFile.parent_path() / folderName;
  std::string vtm;
  vtm += "<?xml version=\"1.0\"?>\n";
  vtm += "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
  vtm += "  <vtkMultiBlockDataSet>\n";
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const std::string fileName = mesh.blocks[b].name + ".vts";
    files.emplace_back(folder / fileName, vtsContent(mesh, b, cellFields));
    vtm += "    <DataSet index=\"" + std::to_string(b) + "\" name=\"" +
           xmlEscaped(mesh.blocks[b].name) + "\" file=\"" +
           xmlEscaped((folderName / fileName).generic_string()) + "\"/>\n";
  }
  vtm += "  </vtkMultiBlockDataSet>\n";
  vtm += "</VTKFile>\n";
  files.emplace_back(vtmFile, vtm);
  return files;
}

}  // namespace passageMesh
