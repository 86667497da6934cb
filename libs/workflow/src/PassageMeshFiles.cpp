#include "passageMesh/workflow/PassageMeshFiles.hpp"

#include <cstdio>
#include <stdexcept>
#include <utility>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/mesh/MeshStatistics.hpp"
#include "passageMesh/polish/OBlockPolish.hpp"
#include "passageMesh/structured/BlockUniformity.hpp"
#include "passageMesh/structured/CgnsWriter.hpp"
#include "passageMesh/structured/VtkWriter.hpp"

namespace passageMesh {

MeshedCase meshCaseAndWrite(const PassageCase& input, const std::filesystem::path& dir,
                            const std::string& tool, bool polish, const std::atomic<bool>* stopPolish) {
  return meshCaseAndWrite(input, buildHohMesh(input.blade, input.condition, input.parameters), dir, tool, polish,
                          stopPolish);
}

MeshedCase meshCaseAndWrite(const PassageCase& input, HohMesh built, const std::filesystem::path& dir,
                            const std::string& tool, bool polish, const std::atomic<bool>* stopPolish,
                            std::vector<FileWriter> alsoWrite) {
  const PassageCondition& condition = input.condition;
  const MeshingParameters& parameters = input.parameters;
  MeshedCase meshed{std::move(built)};
  HohMesh& hoh = meshed.hoh;
  const EllipticReport& s = hoh.smoothing;
  if (s.iterations > 0)
    std::printf("%s: O-block %d x %d nodes; elliptic smoothing: %d multigrid cycles, "
                "residual %.3e (%s)\n", tool.c_str(), parameters.nT, hoh.nN, s.iterations, s.residual,
                s.converged ? "converged" : "NOT converged");
  else  // refused before smoothing (a boundary through the blade, an impossible clustering),
        // or too few rows to smooth
    std::printf("%s: O-block %d x %d nodes; not smoothed\n", tool.c_str(), parameters.nT, hoh.nN);
  if (!hoh.parametersMoved.empty())
    std::printf("  Warning: the mesh with the meshDict's parameters was invalid (%s); built with "
                "them moved: %s\n",
                hoh.firstTryProblem.c_str(), hoh.parametersMoved.c_str());
  if (!hoh.retryWithout.empty())
    std::printf("  meshed by a later try, without orthogonality at %s%s%s%s\n", hoh.retryWithout.c_str(),
                hoh.parametersMoved.empty() ? ": the first was invalid (" : "",
                hoh.parametersMoved.empty() ? hoh.firstTryProblem.c_str() : "",
                hoh.parametersMoved.empty() ? ")" : "");
  if (hoh.valid && hoh.wallBlendLength > HohMeshOptions{}.wallBlendLength)
    std::printf("  rows placed with a wall blend of %g wall spacings: they folded with %g\n",
                hoh.wallBlendLength, HohMeshOptions{}.wallBlendLength);
  if (!hoh.valid) throw std::runtime_error("the mesh is invalid: " + hoh.problem);

  const StructuredBlock& o = hoh.mesh.blocks[1];
  const WallLayerStatistics wall = wallLayerStatistics(o, condition.firstCellHeight);
  std::printf("  first cell height within 2 %% at %.1f %% of the wall nodes (worst %.2f %% at "
              "i = %d)\n  wall-line angle: mean deviation from 90 deg %.3f deg, max %.3f deg "
              "at i = %d\n  H-block cell non-uniformity: inlet %.2e, outlet %.2e\n",
              100 * wall.heightWithin2Percent, 100 * wall.heightMaxError, wall.heightWorstNode,
              wall.angleMeanDeviation, wall.angleMaxDeviation, wall.angleWorstNode,
              blockNonUniformity(hoh.mesh.blocks[0]), blockNonUniformity(hoh.mesh.blocks[2]));

  if (polish) {
    std::fflush(stdout);  // the mesh's figures before the long polish
    OBlockPolishOptions options;
    options.stop = stopPolish;
    // A line for each pass that raises Q: the whole O-block's takes up to a minute.
    options.afterPass = [](const OBlockPolishReport& r) {
      const PolishPass& last = r.passLog.back();
      if (!last.raised) return;
      if (last.halfWidth <= 0)
        std::printf("  polish pass %d, the whole O-block: Q %.6f -> %.6f, %.1f s\n", r.passes(), r.qualityBefore,
                    last.qualityAfter, last.seconds);
      else
        std::printf("  polish pass %d, nodes within %d of cell (%d, %d): Q -> %.6f, %.1f s\n", r.passes(),
                    last.halfWidth, last.i, last.j, last.qualityAfter, last.seconds);
      std::fflush(stdout);
    };
    const OBlockPolishReport p = polishOBlock(hoh.mesh, options);
    meshed.polishInterrupted = p.interrupted;
    if (p.interrupted && p.passes() == 0)
      std::printf("  polish: interrupted (Ctrl-C) before its first step: the mesh is the elliptic one\n");
    else
      std::printf("  polish: Q %.6f -> %.6f (step %d of %d in %d passes), %.1f s: %s%s\n", p.qualityBefore,
                  p.qualityAfter, p.bestStep, p.iterations, p.passes(), p.seconds,
                  p.kept ? "kept" : "not kept (no step raised Q)",
                  p.interrupted ? "; interrupted (Ctrl-C): the rest of the polish not done" : "");
  }
  // The CGNS file, the VTK files and `alsoWrite` are replaced together or not at all.
  std::vector<FileWriter> files = std::move(alsoWrite);
  files.push_back(cgnsFileWriter(hoh.mesh, dir / "mesh" / "passage.cgns"));
  for (auto& [file, content] : vtmFileContents(hoh.mesh, dir / "mesh" / "passage.vtm"))
    files.push_back(fileWithContent(file, std::move(content)));
  writeFilesAtomically(files);
  std::printf("  wrote mesh/passage.cgns, mesh/passage.vtm\n");
  return meshed;
}

}  // namespace passageMesh
