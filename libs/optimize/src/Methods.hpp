#pragma once
// The methods behind optimize() (private to the library). Each runs on the log until its
// budget is used or the stop flag is set and returns the number of starts it made.
#include <string>
#include <vector>

#include "EvaluationLog.hpp"

namespace passageMesh::optimizeDetail {

int runCmaEs(EvaluationLog& log);

// Hooke & Jeeves's pattern search from the best point so far, with steps of initialStep
// (unit-cube lengths; integer dimensions by whole integers); runs until the log is
// finished or every step has shrunk below 1e-7 (integer ones to one) without a gain.
void runPatternSearch(EvaluationLog& log, double initialStep);

const std::vector<std::string>& nloptMethodNames();
int runNlopt(EvaluationLog& log, const std::string& method);

}  // namespace passageMesh::optimizeDetail
