// bladeBoundary: the periodic passage boundary and the O/H block interfaces, for
// inspection and plotting (method.md section 3).
//   reads  constant/bladeParameters.xml, system/passageDict.xml, system/meshDict.xml (optional)
//   writes constant/passageBoundary.dat
#include <cstdio>
#include <sstream>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/PointFile.hpp"
#include "passageMesh/passage/PassageBoundary.hpp"
#include "passageMesh/passage/PassageCase.hpp"

using namespace passageMesh;

namespace {

// `count` x values from a to b inclusive.
std::vector<double> spaced(double a, double b, int count) {
  std::vector<double> x(count);
  for (int k = 0; k < count; ++k) x[k] = a + (b - a) * k / (count - 1);
  return x;
}

}  // namespace

int main(int argc, char* argv[]) {
  return runUtility("bladeBoundary", [&] {
    CommandLine cli("bladeBoundary",
                    "Writes the periodic passage boundary and the O/H interfaces of the case\n"
                    "to constant/passageBoundary.dat (gnuplot: plot it 'index 0' .. 'index 4').");
    if (!cli.parse(argc, argv)) return 0;
    const auto& dir = cli.caseDir();
    const PassageCase input = readPassageCase(dir, "bladeBoundary");
    const BladeShape& blade = input.blade;
    const PassageBoundary boundary(blade, input.condition, input.parameters);

    // The lower boundary has kinks at the edges' x: sample each piece separately.
    std::vector<double> xs = spaced(boundary.inletX(), blade.leadingEdge().x(), 41);
    for (double x : spaced(blade.leadingEdge().x(), blade.trailingEdge().x(), 301)) xs.push_back(x);
    for (double x : spaced(blade.trailingEdge().x(), boundary.outletX(), 41)) xs.push_back(x);
    std::vector<Eigen::Vector2d> lower, upper;
    for (double x : xs) {
      lower.emplace_back(x, boundary.lowerY(x));
      upper.emplace_back(x, boundary.upperY(x));
    }
    auto interface = [&](double x) {
      return std::vector<Eigen::Vector2d>{{x, boundary.lowerY(x)}, {x, boundary.upperY(x)}};
    };
    auto profile = blade.sampleLoop(2000);
    profile.push_back(profile.front());

    std::ostringstream out;
    out << formatPointFile(lower, {"passageMesh bladeBoundary: passage boundary, metres, 'x y'",
                                   "gnuplot blocks (index N), separated by two blank lines:",
                                   "  0 lower periodic boundary, inlet to outlet",
                                   "  1 upper periodic boundary (lower + pitch)",
                                   "  2 inlet O/H interface, lower to upper",
                                   "  3 outlet O/H interface, lower to upper",
                                   "  4 blade profile (closed loop)",
                                   "index 0"})
        << "\n\n" << formatPointFile(upper, {"index 1"})
        << "\n\n" << formatPointFile(interface(boundary.inletInterfaceX()), {"index 2"})
        << "\n\n" << formatPointFile(interface(boundary.outletInterfaceX()), {"index 3"})
        << "\n\n" << formatPointFile(profile, {"index 4"});
    writeFileAtomically(dir / "constant" / "passageBoundary.dat", out.str());
    std::printf("bladeBoundary: pitch %.9g m, inlet x %.9g m, interfaces x %.9g and %.9g m, "
                "outlet x %.9g m\n  wrote constant/passageBoundary.dat\n",
                boundary.pitch(), boundary.inletX(), boundary.inletInterfaceX(),
                boundary.outletInterfaceX(), boundary.outletX());
    return 0;
  });
}
