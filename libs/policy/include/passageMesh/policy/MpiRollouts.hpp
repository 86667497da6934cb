#pragma once
// Rollouts spread over MPI ranks (policyTrain -parallel under mpirun). Rank 0 trains and
// hands each batch's actions to every rank; rank r computes the episodes i with
// i % ranks == r (drawing their tasks again from the episode streams) on its threads, and
// the rewards are summed back to rank 0, where each episode's reward comes from exactly one
// rank: the same numbers as on threads, so the same weights. The other ranks run
// serveRollouts until rank 0 finishes. MPI itself stays inside MpiRollouts.cpp.
#include <string>

#include "passageMesh/policy/RolloutEvaluator.hpp"

namespace passageMesh {

// MPI_Init / MPI_Finalize for the process's lifetime.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

class MpiRollouts final : public RolloutEvaluator {
 public:
  // On rank 0; `environment` must be the same on every rank.
  MpiRollouts(const MpiSession& session, const PolicyEnvironment& environment, int threads);
  ~MpiRollouts() override;  // tells the other ranks to stop
  std::vector<double> rewards(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions,
                              const EpisodeRange& range) override;
  std::vector<double> rewardsWhile(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions,
                                   const EpisodeRange& range, const std::function<void()>& meanwhile) override;
  std::string description() const override;

 private:
  const MpiSession& session_;
  const PolicyEnvironment& environment_;
  int threads_;
};

// On ranks other than 0: computes rewards until rank 0's MpiRollouts ends.
void serveRollouts(const MpiSession& session, const PolicyEnvironment& environment, int threads);

}  // namespace passageMesh
