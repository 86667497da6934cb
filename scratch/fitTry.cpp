#include <cstdio>
#include "passageMesh/blade/BladeFit.hpp"
#include "passageMesh/blade/BladePoints.hpp"
using namespace passageMesh;
int main(int argc, char** argv) {
  for (int a = 1; a < argc; ++a) {
    auto ordered = orderBladePoints(readPointFile(argv[a]));
    auto g = guessBladeParameters(ordered.points);
    auto r = fitBlade(ordered.points);
    auto ga = g.toArray(), pa = r.parameters.toArray();
    auto& q = ordered.points[r.maxDeviationPoint]; printf("maxat %d (%g %g)\n", ordered.inputIndex[r.maxDeviationPoint], q.x(), q.y());
    printf("%s: mean %.3e max %.3e it %d t %.3f valid %d %s\n", argv[a], r.meanDeviation, r.maxDeviation, r.iterations, r.seconds, r.validity.valid, r.validity.reason.c_str());
    for (int k = 0; k < 22; ++k) printf("  %-16s %12.6g %12.6g\n", BladeParameters::names()[k].c_str(), ga[k], pa[k]);
  }
}
