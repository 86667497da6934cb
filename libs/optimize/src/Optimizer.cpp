#include "passageMesh/optimize/Optimizer.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "Methods.hpp"
#include "passageMesh/core/JoinedWords.hpp"

namespace passageMesh {

namespace {

std::map<std::string, ExternalOptimizerMethod>& externalMethods() {
  static std::map<std::string, ExternalOptimizerMethod> methods;
  return methods;
}

std::vector<std::string>& methodNames() {
  static std::vector<std::string> names = [] {
    std::vector<std::string> all{"cmaes"};
    const auto& nlopt = optimizeDetail::nloptMethodNames();
    all.insert(all.end(), nlopt.begin(), nlopt.end());
    return all;
  }();
  return names;
}

}  // namespace

void registerOptimizerMethod(const std::string& name, ExternalOptimizerMethod method) {
  auto& names = methodNames();
  if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  externalMethods()[name] = std::move(method);
}

const std::vector<std::string>& optimizerMethods() { return methodNames(); }

OptimizationResult optimize(const BoxProblem& problem, const BatchObjective& objective,
                            const OptimizerOptions& options) {
  problem.check();
  const auto& methods = optimizerMethods();
  if (std::find(methods.begin(), methods.end(), options.method) == methods.end()) {
    throw std::invalid_argument("optimize: unknown method '" + options.method + "' (known: " + joinedWords(methods, ", ") +
                                ")");
  }
  if (options.budget < 1) throw std::invalid_argument("optimize: the budget must be at least 1 evaluation");
  if (!(options.patternSearchShare >= 0 && options.patternSearchShare <= 1))
    throw std::invalid_argument("optimize: patternSearchShare must be in [0, 1]");
  if (options.start) {
    const Eigen::VectorXd& s = *options.start;
    if (s.size() != problem.dimension() || (s.array() < problem.lower.array()).any() ||
        (s.array() > problem.upper.array()).any())
      throw std::invalid_argument("optimize: the start point is not in the box");
  }
  optimizeDetail::EvaluationLog log(problem, objective, options);
  int starts = 0;
  if (const auto external = externalMethods().find(options.method); external != externalMethods().end()) {
    const Eigen::VectorXd unitStart = options.start ? problem.toUnit(*options.start)
                                                    : Eigen::VectorXd::Constant(problem.dimension(), 0.5);
    starts = external->second(problem.dimension(), unitStart,
                              [&log](const std::vector<Eigen::VectorXd>& points) { return log.evaluate(points); },
                              options);
  } else {
    starts = options.method == "cmaes" ? optimizeDetail::runCmaEs(log)
                                       : optimizeDetail::runNlopt(log, options.method);
  }
  return log.result(options.method, starts);
}

}  // namespace passageMesh
