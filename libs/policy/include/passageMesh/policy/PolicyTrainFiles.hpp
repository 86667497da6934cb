#pragma once
// What policyTrain leaves in a case (docs/case-format.md "policyTrain outputs"):
//   policy/policy.xml, policy/policy.pt   the actor of the best validation so far (Policy.hpp)
//   policy/final.xml, policy/final.pt     the actor as the run (or its interruption) left it
//   policy/checkpoint.pt                  everything -resume needs (PolicyTrainer)
//   postProcessing/policyTrain/learning.csv    episode, meanReward, validFraction,
//                                              criticLoss, sigma, seconds
//   postProcessing/policyTrain/validation.csv  episode, meanReward, medianReward, valid, passages
//   postProcessing/policyTrain/learning.png    both curves (gnuplot)
// All written atomically; the CSVs are rewritten whole from the trainer's records, so a
// resumed run's files hold the whole history.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "passageMesh/policy/PolicyTrainer.hpp"

namespace passageMesh {

struct PolicyTrainPaths {
  explicit PolicyTrainPaths(const std::filesystem::path& caseDir);
  std::filesystem::path policy, finalPolicy, checkpoint, learningCsv, validationCsv, learningPng;
};

// Writes both CSVs and the picture; returns the files written. A missing gnuplot is a
// warning in `warnings`, not an error (the CSVs are what matters). `reference`, when
// given, is drawn as a level line: the validation score of the environment's default
// action, the baseline the policy must beat.
std::vector<std::filesystem::path> writeLearningCurves(const PolicyTrainPaths& paths,
                                                       const PolicyTrainer& trainer,
                                                       std::vector<std::string>* warnings,
                                                       std::optional<double> reference = {});

}  // namespace passageMesh
