#pragma once
// Writes a StructuredMesh for ParaView: a VTK multiblock file (.vtm, XML) that references
// one structured-grid file (.vts, ASCII XML) per block.
//
// Naming: for vtmFile "dir/passage.vtm" the block files are "dir/passage/<block name>.vts"
// (a folder named after the .vtm's stem), referenced from the .vtm by the relative path
// "passage/<block name>.vts", so the pair can be moved together. Block names must
// therefore be usable as file names (no '/', not "." or ".."). Block files of an earlier,
// larger mesh in that folder are left alone (the .vtm no longer references them).
//
// Each .vts has z = 0, extent 0..ni-1 x 0..nj-1 x 0..0, coordinates with 17 significant
// digits, and one Float64 CellData array per BlockField. The block files are written
// first and the .vtm last, each atomically, so a .vtm never references a missing block.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// One value per cell of every block, e.g. a cell quality to colour by.
struct BlockField {
  std::string name;
  // values[block][i + (ni - 1) * j] for cell (i, j), 0 <= i < ni - 1, 0 <= j < nj - 1
  std::vector<std::vector<double>> values;
};

// Throws std::invalid_argument (before writing anything) for a block with fewer than
// 2 x 2 nodes, wrongly sized arrays, a non-finite coordinate or field value, a block
// name unusable as a file name, duplicate block or field names, or a field without one
// value per cell of every block; std::runtime_error naming the file if it cannot be
// written.
void writeVtm(const StructuredMesh& mesh, const std::filesystem::path& vtmFile,
              const std::vector<BlockField>& cellFields = {});

// What writeVtm writes, as (file, content) pairs with the .vtm last, for a tool that
// writes them together with its other outputs (writeFilesAtomically). Same checks.
std::vector<std::pair<std::filesystem::path, std::string>> vtmFileContents(
    const StructuredMesh& mesh, const std::filesystem::path& vtmFile,
    const std::vector<BlockField>& cellFields = {});

}  // namespace passageMesh
