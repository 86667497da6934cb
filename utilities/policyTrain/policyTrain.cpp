// policyTrain: trains the policy that maps a blade passage to its optimal meshing
// parameters by single-step deep reinforcement learning (method.md section 6; issue 12;
// docs/policy.md). Passages are drawn from the sampler's ranges; the case holds only the
// settings and the results.
//   reads  system/policyTrainDict.xml (optional; every key has a default)
//   writes policy/policy.xml + policy.pt (the best policy by validation so far),
//          policy/final.xml + final.pt (the last weights),
//          policy/checkpoint.pt, postProcessing/policyTrain/{learning,validation}.csv,
//          learning.png
// -resume continues from policy/checkpoint.pt; -startFrom FILE continues another run (its
// checkpoint) under this case's settings, e.g. to add searches to a trained policy;
// -actorFrom POLICY.xml starts a new run's actor as a trained policy's (an eight-action
// one's splits at 0);
// -parallel under mpirun spreads the
// rollouts over the ranks. Exit codes: 0 done, 1 bad input, 130 interrupted by Ctrl-C
// (a checkpoint was written: run again with -resume).
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/InterruptFlag.hpp"
#include "passageMesh/policy/MpiRollouts.hpp"
#include "passageMesh/policy/Policy.hpp"
#include "passageMesh/policy/PolicyTrainFiles.hpp"
#include "passageMesh/workflow/OptimizationProgressLine.hpp"

using namespace passageMesh;
namespace po = boost::program_options;

namespace {

std::string commandText(int argc, char* argv[]) {
  std::string text = "policyTrain";
  for (int i = 1; i < argc; ++i) text += std::string(" ") + argv[i];
  return text;
}

// "policyTrain: 12000/100000 episodes, 31.2 per s, mean reward 0.41237 (valid 83.1 %),
//  best validation 0.5512, 47 min 2 s left"
class TrainingProgress {
 public:
  explicit TrainingProgress(long firstEpisode) : first_(firstEpisode) {}
  void operator()(const PolicyTrainer& t, bool force) {
    const double s = std::chrono::duration<double>(Clock::now() - start_).count();
    if (!force && s - last_ < 10.0) return;
    last_ = s;
    const long done = t.episode() - first_;
    const double rate = s > 0 ? done / s : 0.0;
    const double left = rate > 0 ? (t.options().episodes - t.episode()) / rate : 0.0;
    const RewardSummary recent = summarizeRewards(t.recentRewards(1000));
    const double n = std::max(1, recent.count);
    std::string searches;
    if (t.options().searchEvery > 0) {
      const PolicyTrainer::SearchSummary summary = t.searchSummary();
      searches = ", " + std::to_string(summary.searches) + " searches (mean gain " +
                 std::to_string(summary.meanGain) + ", " + std::to_string(t.demonstrations().size()) +
                 " demonstrations)";
    }
    std::fprintf(stderr, "policyTrain: %ld/%ld episodes, %.1f per s, mean reward of the last %d %.5f "
                 "(valid %.1f %%)%s, best validation %s, %s left\n",
                 t.episode(), t.options().episodes, rate, recent.count, recent.mean, 100.0 * recent.valid / n,
                 searches.c_str(),
                 std::isfinite(t.bestValidation()) ? std::to_string(t.bestValidation()).c_str() : "none yet",
                 formatDuration(left).c_str());
  }

 private:
  using Clock = std::chrono::steady_clock;
  long first_;
  Clock::time_point start_ = Clock::now();
  double last_ = 0;
};

int train(const CommandLine& cli, const std::string& command, RolloutEvaluator& rollouts,
          const PassageEnvironment& environment, const PolicyTrainOptions& options) {
  const PolicyTrainPaths paths(cli.caseDir());
  const std::atomic<bool>& stop = installInterruptFlag();  // before anything slow
  PolicyTrainer trainer(options, environment, rollouts);
  const bool resume = cli.values().count("resume") > 0;
  if (resume && cli.values().count("startFrom"))
    throw InputError("command line: -resume and -startFrom: give one (-resume continues this case's run)");
  if (cli.values().count("actorFrom") && (resume || cli.values().count("startFrom")))
    throw InputError("command line: -actorFrom starts a new run: not with -resume or -startFrom");
  if (resume) {
    trainer.resume(paths.checkpoint);
    std::printf("policyTrain: resumed at episode %ld from %s\n", trainer.episode(), paths.checkpoint.c_str());
  } else if (std::filesystem::exists(paths.checkpoint)) {
    throw InputError(paths.checkpoint.string(), 0,
                     "a checkpoint of an earlier run exists: continue it with -resume, or delete it");
  } else if (cli.values().count("startFrom")) {
    const std::filesystem::path from = cli.values()["startFrom"].as<std::string>();
    trainer.resume(from, false);
    std::printf("policyTrain: started at episode %ld from %s, with this case's settings\n", trainer.episode(),
                from.c_str());
  } else if (cli.values().count("actorFrom")) {
    const std::filesystem::path from = cli.values()["actorFrom"].as<std::string>();
    const Policy start = Policy::load(from);
    trainer.startActorFrom(start, environment.stateScaling());
    std::printf("policyTrain: the actor starts as %s's (%d actions; the others at 0), the critic anew\n",
                from.c_str(), start.layout().actionSize);
  }
  std::printf("policyTrain: %ld episodes in batches of %d, networks %s, seed %llu, %s\n", options.episodes,
              options.batchEpisodes, NetworkLayout{0, 0, options.hidden, options.leakySlope}.hiddenText().c_str(),
              static_cast<unsigned long long>(options.seed), rollouts.description().c_str());
  if (options.actorAverageDecay > 0)
    std::printf("policyTrain: the validations and the policy files are the averaged actor's (actorAverageDecay "
                "%.17g)\n", options.actorAverageDecay);
  std::fflush(stdout);

  // The baseline the policy must beat: the defaults' action on the validation passages.
  std::optional<double> baseline;
  if (options.validationPassages > 0 && !environment.defaultAction().empty()) {
    const ValidationRecord d = trainer.validateAction(environment.defaultAction());
    baseline = d.meanReward;
    std::printf("policyTrain: the defaults on the %d validation passages: mean reward %.17g, median %.17g, "
                "%d valid\n", d.passages, d.meanReward, d.medianReward, d.valid);
    if (options.actorStart == ActorStart::meshDict) {
      const ValidationRecord s = trainer.validateAction(options.actorStartAction(environment));
      std::printf("policyTrain: the actor's start (%s) on them: mean reward %.17g, median %.17g, %d valid\n",
                  options.actorStartMeshDict.c_str(), s.meanReward, s.medianReward, s.valid);
    }
    if (cli.values().count("actorFrom")) {
      const ValidationRecord s = trainer.validateCurrentPolicy();
      std::printf("policyTrain: the actor's start on them: mean reward %.17g, median %.17g, %d valid\n",
                  s.meanReward, s.medianReward, s.valid);
    }
    std::fflush(stdout);
  }
  std::vector<std::string> warnings;
  TrainingProgress progress(trainer.episode());
  PolicyTrainer::Events events;
  events.afterBatch = [&](const PolicyTrainer& t) { progress(t, false); };
  events.newBestValidation = [&](const PolicyTrainer& t) {
    writePolicyFiles(paths.policy, t.learner(), environment.stateScaling(), PolicyProvenance{t.episode(), t.bestValidation(), command});
  };
  events.learnerRestored = [&](const PolicyTrainer& t) {
    const ValidationRecord& v = t.validationCurve().back();
    std::printf("policyTrain: validation at episode %ld meshed %d of %d passages: the learner goes back to its state "
                "at the best validation (%.17g), restore %zu\n",
                t.episode(), v.valid, v.passages, t.bestValidation(), t.restores().size());
    std::fflush(stdout);
  };
  events.checkpointDue = [&](const PolicyTrainer& t) {
    t.saveCheckpoint(paths.checkpoint);
    writeLearningCurves(paths, t, &warnings, baseline);
  };
  const bool done = trainer.run(&stop, events);
  trainer.saveCheckpoint(paths.checkpoint);
  // final.xml states the validation of its own weights: the curve's last point unless the
  // run stopped between two validations (Ctrl-C), then one more pass over the passages.
  double finalValidation = 0;
  if (options.validationPassages > 0) {
    const auto& curve = trainer.validationCurve();
    if (!curve.empty() && curve.back().episode == trainer.episode()) {
      finalValidation = curve.back().meanReward;
    } else {
      const ValidationRecord v = trainer.validateCurrentPolicy();
      finalValidation = v.meanReward;
      std::printf("policyTrain: validation of the weights at episode %ld: mean reward %.17g, median %.17g, "
                  "%d of %d valid\n", v.episode, v.meanReward, v.medianReward, v.valid, v.passages);
    }
  }
  writePolicyFiles(paths.finalPolicy, trainer.learner(), environment.stateScaling(),
                   PolicyProvenance{trainer.episode(), finalValidation, command});
  const auto written = writeLearningCurves(paths, trainer, &warnings, baseline);
  progress(trainer, true);
  for (const auto& w : warnings) std::cerr << "policyTrain: warning: " << w << "\n";
  if (!trainer.validationCurve().empty()) {
    const ValidationRecord& v = trainer.validationCurve().back();
    std::printf("policyTrain: last validation (episode %ld): mean reward %.17g, median %.17g, %d of %d valid; "
                "best %.17g\n", v.episode, v.meanReward, v.medianReward, v.valid, v.passages,
                trainer.bestValidation());
  }
  std::printf("  wrote %s\n  wrote %s\n", paths.checkpoint.c_str(), paths.finalPolicy.c_str());
  if (std::filesystem::exists(paths.policy)) std::printf("  wrote %s\n", paths.policy.c_str());
  for (const auto& f : written) std::printf("  wrote %s\n", f.c_str());
  if (!done) {
    std::fprintf(stderr, "policyTrain: interrupted at episode %ld; continue with -resume\n", trainer.episode());
    return interruptedExitCode;
  }
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  // MPI starts before anything else reads the command line, as mpirun expects.
  bool parallel = false;
  for (int i = 1; i < argc; ++i)
    parallel = parallel || std::string(argv[i]) == "-parallel" || std::string(argv[i]) == "--parallel";
  // Several copies under mpirun without -parallel would each train on the same files.
  const char* ranks = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (!parallel && ranks && std::atoi(ranks) > 1) {
    std::fprintf(stderr, "policyTrain: error: started as %s MPI ranks without -parallel; add -parallel "
                 "(or run one process)\n", ranks);
    return 1;
  }
  std::optional<MpiSession> mpi;
  if (parallel) mpi.emplace(argc, argv);
  const bool worker = mpi && mpi->rank() != 0;

  return runUtility("policyTrain", [&] {
    CommandLine cli("policyTrain",
                    "Trains the policy mapping a blade passage to its optimal meshing parameters\n"
                    "(single-step actor-critic, docs/policy.md) on passages drawn from the\n"
                    "sampler's ranges. Settings: system/policyTrainDict.xml. Ctrl-C stops after the\n"
                    "batch under way and writes a checkpoint (exit code 130); -resume continues.");
    cli.addOptions()
        ("resume", "continue from policy/checkpoint.pt")
        ("startFrom", po::value<std::string>(),
         "start from another run's checkpoint FILE (its weights, optimisers, replay buffer, curves and "
         "episode count; the same networks) and go on with this case's settings")
        ("actorFrom", po::value<std::string>(),
         "start the actor as a trained policy FILE's (a single policy of this case's state scaling and "
         "networks; actions it lacks, the splits of an eight-action policy, at 0); the critic learns anew")
        ("parallel", "spread the rollouts over MPI ranks (run under mpirun)")
        ("episodes", po::value<long>(), "override <episodes> of the dictionary")
        ("threads", po::value<int>(), "override <threads> of the dictionary (0 = all cores)");
    if (!cli.parse(argc, argv)) return 0;
    PolicyTrainOptions options = readPolicyTrainDict(cli.caseDir() / "system" / "policyTrainDict.xml");
    if (cli.values().count("episodes")) {
      options.episodes = cli.values()["episodes"].as<long>();
      if (options.episodes < 1) throw InputError("command line: -episodes: at least 1");
    }
    if (cli.values().count("threads")) {
      options.threads = cli.values()["threads"].as<int>();
      if (options.threads < 0) throw InputError("command line: -threads: expected 0 (all cores) or more");
    }
    const PassageEnvironment environment = options.passageEnvironment();
    if (worker) {
      serveRollouts(*mpi, environment, options.threads);
      return 0;
    }
    std::unique_ptr<RolloutEvaluator> rollouts;
    if (mpi)
      rollouts = std::make_unique<MpiRollouts>(*mpi, environment, options.threads);
    else
      rollouts = std::make_unique<ThreadRollouts>(options.threads);
    return train(cli, commandText(argc, argv), *rollouts, environment, options);
  });
}
