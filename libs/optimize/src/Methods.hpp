#pragma once
// The methods behind optimize() (private to the library). Each runs on the log until its
// budget is used or the stop flag is set and returns the number of starts it made.
#include <string>
#include <vector>

#include "EvaluationLog.hpp"

namespace passageMesh::optimizeDetail {

int runCmaEs(EvaluationLog& log);

const std::vector<std::string>& nloptMethodNames();
int runNlopt(EvaluationLog& log, const std::string& method);

}  // namespace passageMesh::optimizeDetail
