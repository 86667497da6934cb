// optimizerBenchmark: the optimiser table of docs/benchmarks.md.
//   build/bench/optimizerBenchmark [budget=3000] [seeds=10] [restartsPerRound=1] [methods...]
// Runs every method on every synthetic objective (SyntheticObjectives.hpp) with seeds
// 1..seeds and prints a Markdown table: the median number of evaluations until the best
// value reaches 0.99 of the maximum (a run that never does counts as the budget + 1, so a
// median above the budget means "not reached in most runs"), the runs that reached it,
// and the median of the best values at the end.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "passageMesh/optimize/Optimizer.hpp"
#include "passageMesh/optimize/SyntheticObjectives.hpp"

using namespace passageMesh;

namespace {

template <typename T>
T median(std::vector<T> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

long evaluationsToReach(const OptimizationHistory& history, double target) {
  for (const Evaluation& e : history)
    if (e.bestSoFar >= target) return e.index + 1;
  return -1;
}

}  // namespace

int main(int argc, char* argv[]) {
  const long budget = argc > 1 ? std::max(1L, std::atol(argv[1])) : 3000;
  const int seeds = argc > 2 ? std::max(1, std::atoi(argv[2])) : 10;
  const int restartsPerRound = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1;
  std::vector<std::string> methods(argv + std::min(argc, 4), argv + argc);
  if (methods.empty()) methods = optimizerMethods();
  constexpr double target = 0.99;

  std::printf("| objective | method | median evaluations to 0.99 | runs reaching 0.99 | "
              "median best | time per run [ms] |\n|---|---|---|---|---|---|\n");
  for (const SyntheticProblem& problem : syntheticProblems()) {
    for (const std::string& method : methods) {
      std::vector<double> needed, best;
      int reached = 0;
      const auto begin = std::chrono::steady_clock::now();
      for (int seed = 1; seed <= seeds; ++seed) {
        OptimizerOptions options;
        options.method = method;
        options.budget = budget;
        options.seed = static_cast<std::uint64_t>(seed);
        options.threads = 1;
        options.restartsPerRound = restartsPerRound;
        const OptimizationResult r = optimize(problem.box, evaluateInParallel(problem.objective, 1), options);
        const long n = evaluationsToReach(r.history, target);
        reached += n > 0;
        needed.push_back(n > 0 ? static_cast<double>(n) : static_cast<double>(budget + 1));
        best.push_back(r.bestValue);
      }
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
      const double m = median(needed);
      const std::string shown = m > static_cast<double>(budget) ? "> " + std::to_string(budget)
                                                                : std::to_string(static_cast<long>(m));
      std::printf("| %s | %s | %s | %d/%d | %.4f | %.1f |\n", problem.name.c_str(), method.c_str(),
                  shown.c_str(), reached, seeds, median(best), ms / seeds);
      std::fflush(stdout);
    }
  }
  return 0;
}
