#include "passageMesh/policy/MpiRollouts.hpp"

#include <mpi.h>

#include <array>
#include <cstdio>
#include <exception>
#include <string>

#include "passageMesh/core/ParallelFor.hpp"

namespace passageMesh {

namespace {

// The header rank 0 broadcasts before each batch: command, seed, first episode, count, step,
// purpose (EpisodeRange).
enum Command : std::uint64_t { stopCommand = 0, evaluateCommand = 1 };
using Header = std::array<std::uint64_t, 6>;

void broadcastHeader(Header& h) {
  MPI_Bcast(h.data(), static_cast<int>(h.size()), MPI_UINT64_T, 0, MPI_COMM_WORLD);
}

// Every rank's part of one batch; the sum over ranks lands on rank 0. On rank 0, `meanwhile`
// (if any) runs on this thread while the rank's part is computed on others.
std::vector<double> evaluateBatch(const MpiSession& session, const PolicyEnvironment& environment,
                                  int threads, const Header& h, std::vector<EpisodeTask> tasks,
                                  PolicyBatch& actions, const std::function<void()>& meanwhile = {}) {
  const int count = static_cast<int>(h[3]);
  actions.resize(count, environment.actionSize());
  MPI_Bcast(actions.data(), static_cast<int>(actions.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (tasks.empty()) {
    tasks.resize(static_cast<std::size_t>(count));
    const EpisodeRange range{h[1], h[2], h[4], static_cast<EpisodePurpose>(h[5])};
    for (int i = session.rank(); i < count; i += session.size())
      tasks[static_cast<std::size_t>(i)] =
          environment.draw(range.seed, range.episode(static_cast<std::size_t>(i)), range.purpose);
  }
  std::vector<double> mine, all(static_cast<std::size_t>(count), 0.0);
  std::exception_ptr sliceFailure, meanwhileFailure;
  const auto slice = [&] {
    try {
      rewardsOfSlice(tasks, actions, session.rank(), session.size(), threads, mine);
    } catch (...) {
      sliceFailure = std::current_exception();
    }
  };
  try {
    if (meanwhile)
      runBeside(slice, meanwhile);
    else
      slice();
  } catch (...) {  // (the slice throws nothing: this is meanwhile's)
    meanwhileFailure = std::current_exception();
  }
  if (sliceFailure) {
    // The other ranks wait in the collective below: end them all rather than hang.
    std::string what = "unknown error";
    try {
      std::rethrow_exception(sliceFailure);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    std::fprintf(stderr, "policyTrain: error: rank %d: %s\n", session.rank(), what.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  // Rank 0's own failure (the learner's) after the collective, so the ranks stay in step.
  MPI_Reduce(mine.data(), all.data(), count, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  if (meanwhileFailure) std::rethrow_exception(meanwhileFailure);
  return all;
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  // Only the main thread calls MPI; rollouts run on other threads meanwhile.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  if (provided < MPI_THREAD_FUNNELED) {
    std::fprintf(stderr, "policyTrain: error: this MPI library gives no thread support (MPI_THREAD_FUNNELED "
                         "asked, level %d given): the rollouts run on threads beside MPI's\n", provided);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

MpiRollouts::MpiRollouts(const MpiSession& session, const PolicyEnvironment& environment, int threads)
    : session_(session), environment_(environment), threads_(threads) {}

MpiRollouts::~MpiRollouts() {
  Header h{stopCommand, 0, 0, 0, 0, 0};
  broadcastHeader(h);
}

std::vector<double> MpiRollouts::rewards(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions,
                                         const EpisodeRange& range) {
  return rewardsWhile(tasks, actions, range, {});
}

std::vector<double> MpiRollouts::rewardsWhile(const std::vector<EpisodeTask>& tasks, const PolicyBatch& actions,
                                              const EpisodeRange& range, const std::function<void()>& meanwhile) {
  Header h{evaluateCommand, range.seed, range.first, tasks.size(), range.step,
           static_cast<std::uint64_t>(range.purpose)};
  broadcastHeader(h);
  PolicyBatch copy = actions;
  return evaluateBatch(session_, environment_, threads_, h, tasks, copy, meanwhile);
}

std::string MpiRollouts::description() const {
  return std::to_string(session_.size()) + " MPI ranks x " + std::to_string(resolvedThreads(threads_)) +
         " rollout threads";
}

void serveRollouts(const MpiSession& session, const PolicyEnvironment& environment, int threads) {
  for (;;) {
    Header h{};
    broadcastHeader(h);
    if (h[0] == stopCommand) return;
    PolicyBatch actions;
    evaluateBatch(session, environment, threads, h, {}, actions);
  }
}

}  // namespace passageMesh
