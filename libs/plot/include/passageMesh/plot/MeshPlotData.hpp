#pragma once
// A mesh as gnuplot data (plain text, 17 significant digits).
#include <string>
#include <vector>

#include "passageMesh/structured/StructuredMesh.hpp"

namespace passageMesh {

// Grid lines of every block, "x y" per line, a blank line between lines (so `with lines`
// does not join them): every `stride`-th line of each index direction, and always the
// block's edges.
std::string gridLinesData(const StructuredMesh& mesh, int stride);

// One block's cells as closed polygons of four corners, "x y value", a blank line after
// each: `plot ... using 1:2:3 with filledcurves closed fc palette` fills cell (i, j) with
// the colour of values[i + (ni - 1) * j].
std::string cellValuesData(const StructuredBlock& block, const std::vector<double>& values);

// One block's row of nodes j as a line "x y" (the O-block's row 0 is the blade).
std::string nodeRowData(const StructuredBlock& block, int j);

}  // namespace passageMesh
