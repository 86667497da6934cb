#pragma once
// The progress of a long optimisation on stderr: evaluations done of the budget, the best
// value, the time per evaluation and the time left. On a terminal one line is rewritten in
// place (\r); into a file or pipe (logs, tests) a line is added every 5 % of the budget
// or 10 s, whichever comes first, so a log stays short.
#include <chrono>
#include <cstdio>
#include <string>

#include "passageMesh/optimize/Optimizer.hpp"

namespace passageMesh {

// "12/1000 evaluations, best Q 0.53190, 1.52 s per evaluation, 25 min 2 s left"
std::string formatOptimizationProgress(const OptimizationProgress& progress, double seconds);
// "3 s", "2 min 5 s", "1 h 2 min"
std::string formatDuration(double seconds);

class OptimizationProgressLine {
 public:
  // Lines start with "TOOL: "; the clock starts now.
  explicit OptimizationProgressLine(std::string tool, std::FILE* stream = stderr);

  // OptimizerOptions::progress (called from one thread at a time).
  void operator()(const OptimizationProgress& progress);
  // Ends a line rewritten in place; call before printing anything else.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string tool_;
  std::FILE* stream_;
  bool terminal_;
  bool lineOpen_ = false;
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastLine_ = start_;
  long nextStep_ = 0;  // evaluations at which the next line is due (file or pipe)
};

}  // namespace passageMesh
