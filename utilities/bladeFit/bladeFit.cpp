// bladeFit: fits the blade shape parameters to the scattered points of a blade.
//   reads  constant/bladePoints.dat, system/bladeFitDict.xml (optional)
//   writes constant/bladeParameters.xml, constant/bladeProfile.dat
#include <cstdio>
#include <iostream>

#include "passageMesh/blade/BladeFit.hpp"
#include "passageMesh/blade/BladeParametersFile.hpp"
#include "passageMesh/blade/BladePoints.hpp"
#include "passageMesh/blade/BladeShape.hpp"
#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/Dictionary.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/PointFile.hpp"

using namespace passageMesh;

int main(int argc, char* argv[]) {
  return runUtility("bladeFit", [&] {
    CommandLine cli("bladeFit",
                    "Fits camber/thickness blade shape parameters to the points in\n"
                    "constant/bladePoints.dat; writes constant/bladeParameters.xml and\n"
                    "constant/bladeProfile.dat.");
    cli.addOptions()
        ("threads", boost::program_options::value<int>()->default_value(0),
         "threads for the multi-start search (0 = all cores; the result does not depend on it)");
    if (!cli.parse(argc, argv)) return 0;

    BladeFitOptions options;
    options.threads = cli.values()["threads"].as<int>();
    if (options.threads < 0)
      throw std::runtime_error("-threads " + std::to_string(options.threads) +
                               ": expected 0 (all cores) or a positive count");
    int profilePoints = 2000;
    const auto dictFile = cli.caseDir() / "system" / "bladeFitDict.xml";
    if (std::filesystem::exists(dictFile)) {
      const Dictionary dict = Dictionary::read(
          dictFile, "bladeFitDict", {"profilePoints", "targetMaxDeviation", "maxRounds"});
      auto refuse = [&](const std::string& key, const std::string& expected) {
        throw InputError(dictFile.string(), dict.line(key),
                         "<" + key + "> " + dict.text(key) + " is out of range, expected " + expected);
      };
      if (dict.has("profilePoints")) {
        const long n = dict.integer("profilePoints");
        if (n < 2000 || n > 1000000) refuse("profilePoints", "2000..1000000");
        profilePoints = static_cast<int>(n);
      }
      if (dict.has("targetMaxDeviation")) {
        options.targetMaxDeviation = dict.scalar("targetMaxDeviation");
        if (!(options.targetMaxDeviation > 0 && options.targetMaxDeviation <= 0.1))
          refuse("targetMaxDeviation", "a fraction of the chord in (0, 0.1]");
      }
      if (dict.has("maxRounds")) {
        const long rounds = dict.integer("maxRounds");
        if (rounds < 1 || rounds > 4) refuse("maxRounds", "1..4");
        options.maxRounds = static_cast<int>(rounds);
      }
    }

    const auto constant = cli.caseDir() / "constant";
    const PointSet input = readPointFile(constant / "bladePoints.dat");
    const OrderedBladePoints ordered = orderBladePoints(input);
    std::printf("bladeFit: %zu points from %s (%s%s)\n", ordered.points.size(),
                input.file.c_str(), ordered.reversed ? "clockwise, reversed" : "counter-clockwise",
                ordered.closed ? "; the repeated closing point dropped" : "");

    const BladeFitResult fit = fitBlade(ordered.points, options);
    const BladeParameters& p = fit.parameters;
    std::printf("  chord %.9g m, stagger %.6g deg, thetaLe %.6g deg, thetaTe %.6g deg\n", p.chord,
                p.stagger, p.thetaLe, p.thetaTe);
    std::printf("  deviation of the points from the fit: mean %.6e m (%.5f %% chord), "
                "max %.6e m (%.5f %% chord)\n",
                fit.meanDeviation, 100 * fit.meanDeviation / p.chord, fit.maxDeviation,
                100 * fit.maxDeviation / p.chord);
    std::printf("  %d starts in %d rounds, %d iterations, %.3f s\n", fit.starts, fit.rounds,
                fit.iterations, fit.seconds);
    if (!fit.validity)
      throw std::runtime_error(input.file + ": no valid blade fits these points (best fit: " +
                               fit.validity.reason + ")");

    BladeFitReport report;
    report.pointsFile = "constant/bladePoints.dat";
    report.points = static_cast<int>(ordered.points.size());
    report.meanDeviation = fit.meanDeviation;
    report.maxDeviation = fit.maxDeviation;
    report.maxDeviationLine =
        fit.maxDeviationPoint >= 0 ? input.lines[ordered.inputIndex[fit.maxDeviationPoint]] : 0;
    report.iterations = fit.iterations;
    report.starts = fit.starts;
    report.seconds = fit.seconds;

    // Everything is computed before anything is written; each file is replaced atomically.
    auto loop = BladeShape(p).sampleLoop(profilePoints);
    loop.push_back(loop.front());  // closed: the first point repeated at the end
    const std::string profile = formatPointFile(
        loop, {"passageMesh bladeFit: fitted blade profile, closed loop (last point = first)",
               "counter-clockwise from the leading edge along the lower side; metres", "x y"});
    writeFilesAtomically({{constant / "bladeProfile.dat", profile},
                          {constant / "bladeParameters.xml", bladeParametersXml(p, report)}});
    std::printf("  wrote constant/bladeParameters.xml, constant/bladeProfile.dat\n");
    return 0;
  });
}
