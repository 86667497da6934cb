#include "passageMesh/workflow/OptimizationProgressLine.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace passageMesh {

std::string formatDuration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[64];
  if (s < 60)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ld min %ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld h %ld min", s / 3600, s / 60 % 60);
  return text;
}

std::string formatOptimizationProgress(const OptimizationProgress& progress, double seconds) {
  const long done = std::max(1L, progress.evaluations);
  const double perEvaluation = seconds / static_cast<double>(done);
  const double left = perEvaluation * static_cast<double>(std::max(0L, progress.budget - progress.evaluations));
  char text[160];
  std::snprintf(text, sizeof text, "%ld/%ld evaluations, best Q %.5f, %.3g s per evaluation, %s left",
                progress.evaluations, progress.budget, progress.bestValue, perEvaluation,
                formatDuration(left).c_str());
  return text;
}

OptimizationProgressLine::OptimizationProgressLine(std::string tool, std::FILE* stream)
    : tool_(std::move(tool)), stream_(stream), terminal_(::isatty(::fileno(stream)) != 0) {}

void OptimizationProgressLine::operator()(const OptimizationProgress& progress) {
  const Clock::time_point now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const std::string line = tool_ + ": " + formatOptimizationProgress(progress, seconds);
  if (terminal_) {
    // Padded so that a shorter line hides the end of a longer one.
    std::fprintf(stream_, "\r%-100s", line.c_str());
    lineOpen_ = true;
  } else {
    const long step = std::max(1L, progress.budget / 20);
    const bool due = progress.evaluations >= nextStep_ || progress.evaluations >= progress.budget ||
                     now - lastLine_ >= std::chrono::seconds(10);
    if (!due) return;
    std::fprintf(stream_, "%s\n", line.c_str());
    lastLine_ = now;
    nextStep_ = (progress.evaluations / step + 1) * step;
  }
  std::fflush(stream_);
}

void OptimizationProgressLine::finish() {
  if (lineOpen_) std::fprintf(stream_, "\n");
  lineOpen_ = false;
  std::fflush(stream_);
}

}  // namespace passageMesh
