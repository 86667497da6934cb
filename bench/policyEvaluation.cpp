// policyEvaluation: a policy (or the defaults) on sampler passages, against the best an
// optimiser finds for each passage (issue 12 must-show: one-shot Q / iterative best).
//   policyEvaluation POLICY.xml|defaults SEED COUNT [BUDGET [OUT.csv|- [EDGE_RADII [BESTS.csv]]]]
// Passages are PassageEnvironment's episodes 0..COUNT-1 of stream SEED (policyTrain's
// validation set is stream 20261202), their edge radii drawn as EDGE_RADII says
// (halfLogUniform, the default, as policyTrain draws them since the twelfth session, or
// uniform, as before); a policy sees them under its own state scaling. With BESTS.csv (the
// OUT.csv of an earlier run on the same SEED, COUNT, BUDGET and EDGE_RADII) the CMA-ES
// searches are not run again: their bests do not depend on the policy (CMA-ES starts at
// the defaults with seed 1), so each passage's best is the larger of the file's bestQ and
// this one-shot Q, as the search would give. An ensemble's one shot is policyMesh's: its
// mean action, or where that mesh is invalid its members' own actions in turn
// (Policy::actionsInTurn; the bound counts below are the mean action's). With BUDGET > 0, CMA-ES
// (iterOptimize's default method) searches each passage's meshing parameters from the
// defaults with that many meshes; the ratio is one-shot Q / that best. Prints a summary,
// for a policy how often each action sits at a bound of its range (|a| >= 0.98 in scaled
// units: there tanh's slope is under 4 %, so training barely moves it back), and writes
// one row per passage to OUT.csv and, with BUDGET, the ratios' histogram to
// OUT.png (gnuplot).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/GnuplotRun.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/ParallelFor.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/policy/PolicyEnvironment.hpp"
#include "passageMesh/policy/PolicyTrainOptions.hpp"
#include "PassageSearch.hpp"

using namespace passageMesh;

int main(int argc, char* argv[]) {
  // A missing or corrupt file ends in one line on stderr and exit code 1, not a crash.
  return runUtility("policyEvaluation", [&] {
    if (argc < 4) {
      std::fprintf(stderr, "usage: policyEvaluation POLICY.xml|defaults SEED COUNT [BUDGET [OUT.csv|- "
                           "[halfLogUniform|uniform [BESTS.csv]]]]\n");
      return 2;
    }
    const std::string which = argv[1];
    const std::uint64_t seed = std::stoull(argv[2]);
    const int count = std::stoi(argv[3]);
    const long budget = argc > 4 ? std::stol(argv[4]) : 0;
    std::optional<Policy> policy;
    if (which != "defaults") policy = Policy::load(which);
    const EdgeRadiusDraw edgeRadii = edgeRadiusDrawNamed(argc > 6 ? argv[6] : "halfLogUniform");
    std::vector<double> earlierBests;
    if (argc > 7) {
      std::ifstream in(argv[7]);
      if (!in) throw InputError(argv[7], 0, "cannot read the earlier run's CSV");
      std::string line;
      std::getline(in, line);
      for (int row = 0; std::getline(in, line); ++row) {
        std::istringstream fields(line);
        std::string passage, oneShot, best;
        if (!std::getline(fields, passage, ',') || !std::getline(fields, oneShot, ',') ||
            !std::getline(fields, best, ',') || std::stoi(passage) != row)
          throw InputError(argv[7], row + 2, "expected 'passage,oneShotQ,bestQ,ratio' with passage " +
                                                 std::to_string(row));
        earlierBests.push_back(std::stod(best));
      }
      if (static_cast<int>(earlierBests.size()) != count || budget <= 0)
        throw InputError(argv[7], 0, "holds " + std::to_string(earlierBests.size()) + " passages; expected " +
                                         std::to_string(count) + " and a BUDGET above 0");
    }
    const PassageEnvironment environment(
        edgeRadii,
        policy ? policy->stateScaling() : policyStateScaling(BladeParameterRange::readDefault()));

    struct Row {
      double oneShot = -1, best = -1;
    };
    std::vector<Row> rows(static_cast<std::size_t>(count));
    constexpr double atBound = 0.98;  // scaled units; tanh's slope there is under 4 %
    std::vector<int> atLower(policyActionSize, 0), atUpper(policyActionSize, 0);
    for (int i = 0; i < count; ++i) {
      const EpisodeTask task = environment.draw(seed, static_cast<std::uint64_t>(i), EpisodePurpose::validation);
      std::vector<double> action = environment.defaultAction();
      std::vector<PolicyAction> inTurn;
      if (policy) {
        PolicyState s;
        std::copy(task.state.begin(), task.state.end(), s.begin());
        inTurn = policy->actionsInTurn(s);
        const PolicyAction& a = inTurn.front();
        action.assign(a.begin(), a.end());
        for (int k = 0; k < policyActionSize; ++k) {
          atLower[static_cast<std::size_t>(k)] += a[static_cast<std::size_t>(k)] <= -atBound;
          atUpper[static_cast<std::size_t>(k)] += a[static_cast<std::size_t>(k)] >= atBound;
        }
      }
      Row& row = rows[static_cast<std::size_t>(i)];
      row.oneShot = task.reward(action);
      // as policyMesh: where the mean action's mesh is invalid, the members' own in turn
      for (std::size_t m = 1; m < inTurn.size() && row.oneShot <= -1; ++m)
        row.oneShot = task.reward(std::vector<double>(inTurn[m].begin(), inTurn[m].end()));
      if (!earlierBests.empty()) {
        row.best = std::max(row.oneShot, earlierBests[static_cast<std::size_t>(i)]);
      } else if (budget > 0) {
        row.best = std::max(row.oneShot,
                            bench::searchPassage(task, environment.defaultAction(), budget).bestValue);
      }
      std::fprintf(stderr, "passage %d: one-shot Q %.6f%s\n", i, row.oneShot,
                   budget > 0 ? (", best " + std::to_string(row.best)).c_str() : "");
    }

    std::string csv = "passage,oneShotQ,bestQ,ratio\n";
    std::vector<double> q, ratios;
    int bothValid = 0;
    for (int i = 0; i < count; ++i) {
      const Row& r = rows[static_cast<std::size_t>(i)];
      q.push_back(r.oneShot);
      double ratio = -1;
      if (budget > 0 && r.best > 0) {
        ratio = r.oneShot > -1 ? r.oneShot / r.best : 0.0;
        ratios.push_back(ratio);
        bothValid += r.oneShot > -1;
      }
      char line[160];
      std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g\n", i, r.oneShot, r.best, ratio);
      csv += line;
    }
    const RewardSummary oneShot = summarizeRewards(q);
    std::printf("%s on %d passages of stream %llu: mean reward %.6f, median %.6f, %d valid\n", which.c_str(), count,
                static_cast<unsigned long long>(seed), oneShot.mean, oneShot.median, oneShot.valid);
    if (policy) {
      std::printf("  actions at a bound (|a| >= %.2f) of %d passages:", atBound, count);
      for (int k = 0; k < policyActionSize; ++k)
        std::printf(" %s %d low %d high%s", MeshingParameters::names()[static_cast<std::size_t>(k)].c_str(),
                    atLower[static_cast<std::size_t>(k)], atUpper[static_cast<std::size_t>(k)], k + 1 < policyActionSize ? ";" : "\n");
    }
    if (budget > 0)
      std::printf("  against CMA-ES with %ld meshes from the defaults: %zu passages with a valid best; ratio "
                  "one-shot / best: median %.4f, worst %.4f (an invalid one-shot mesh counts 0); %d both valid\n",
                  budget, ratios.size(), summarizeRewards(ratios).median,
                  ratios.empty() ? 0.0 : *std::min_element(ratios.begin(), ratios.end()), bothValid);
    if (argc > 5 && std::string(argv[5]) != "-") {
      const std::filesystem::path out = argv[5];
      writeFileAtomically(out, csv);
      if (budget > 0) {
        GnuplotRun plot;
        std::filesystem::path png = out;
        png.replace_extension(".png");
        plot.run(gnuplotPngTerminal(900, 550) + plot.output(png) +
                 "set datafile separator ','\nset grid\nset style fill solid 0.6\n"
                 "set xlabel 'one-shot Q / best Q of CMA-ES (" + std::to_string(budget) +
                 " meshes); invalid one-shot mesh = 0'\nset ylabel 'passages'\n"
                 "set title '" + which + ": " + std::to_string(ratios.size()) +
                 " sampler passages with a valid best mesh'\nset xrange [-0.025:1.075]\nset boxwidth 0.045\n"
                 "bin(x) = 0.05 * floor(x / 0.05 + 0.5)\n"
                 "plot " + gnuplotQuoted(out.string()) +
                 " every ::1 using (bin($4)):(1.0) smooth frequency with boxes notitle\n");
      }
    }
    return 0;
  });
}
