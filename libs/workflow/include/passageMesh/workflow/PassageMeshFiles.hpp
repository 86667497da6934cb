#pragma once
// Meshing a case as ellipticMesh and policyMesh do: build the HOH mesh, print what a CFD
// engineer checks (smoothing convergence, first cell height, wall-line angles, H-block
// uniformity), refuse an invalid mesh, and write mesh/passage.cgns and mesh/passage.vtm
// (+ mesh/passage/<block>.vts) atomically.
#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/mesh/HohMesh.hpp"
#include "passageMesh/passage/PassageCase.hpp"

namespace passageMesh {

// Lines start with "TOOL: ". Throws std::runtime_error ("the mesh is invalid: ...") and
// writes nothing when the mesh is invalid. With `polish`, the valid mesh's O-block is
// polished (OBlockPolish.hpp: kept only where Q rises) before it is written, with a line
// for each pass that raises Q; a non-null `stopPolish` that turns true (Ctrl-C:
// installInterruptFlag) ends the polish early, and the mesh is written with the best
// nodes so far.
struct MeshedCase {
  HohMesh hoh;                     // as written
  bool polishInterrupted = false;  // stopPolish ended the polish before its last pass
};
MeshedCase meshCaseAndWrite(const PassageCase& input, const std::filesystem::path& caseDir,
                            const std::string& tool, bool polish = false,
                            const std::atomic<bool>* stopPolish = nullptr);
// The same with the mesh of input's parameters already built (buildHohMesh), for a tool
// that built it to choose among parameters (policyMesh's ensemble fallback); `alsoWrite`
// (policyMesh's meshDict.xml) is written together with the mesh files, all or none.
MeshedCase meshCaseAndWrite(const PassageCase& input, HohMesh built, const std::filesystem::path& caseDir,
                            const std::string& tool, bool polish = false,
                            const std::atomic<bool>* stopPolish = nullptr,
                            std::vector<FileWriter> alsoWrite = {});

// The help of the `-polish` option of the tools that call meshCaseAndWrite.
inline constexpr const char* polishOptionHelp =
    "polish the O-block by optimisation after the elliptic smoothing, kept where Q rises "
    "(docs/elliptic-smoothing.md \"Polish\"; half a minute to a minute and a half at nO = 30000; "
    "Ctrl-C ends it early and writes the mesh with the polish so far, exit code 130)";

}  // namespace passageMesh
