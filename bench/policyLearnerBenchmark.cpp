// policyLearnerBenchmark: the single-step actor-critic on the toy problem (ToyEnvironment:
// known optimum, cheap reward), so the learner's cost and its learning can be measured
// apart from the mesher (docs/benchmarks.md "Policy learner").
//   policyLearnerBenchmark [EPISODES [HIDDEN [LEARNING_RATE [SEED [CRITIC_UPDATES
//                          [ACTOR_EVERY [MINIBATCH [CRITIC_MODEL [CLIFF [NOISE [BARRIER]]]]]]]]]]]
//     HIDDEN: layer widths separated by commas ("512,256,256,128", the paper's)
//     CRITIC_MODEL: reward (default) or validityAndQuality (policyTrainDict's criticModel)
//     CLIFF: actions whose first entry is more than CLIFF above the optimum's get -1
//            (ToyEnvironment; default, or inf: none)
//     NOISE: sigma of the first 1000 episodes, then NOISE / 3 (cos + 1), the shipped
//            policy's schedule at 0.3 (default: the paper's, 1 then 0.25 (cos + 1))
//     BARRIER: validityBarrier (with validityAndQuality; default 0: the expected reward)
// Prints the RMS action error on 1000 unseen states every tenth of the run and the learner
// time per episode (one thread).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

#include "passageMesh/core/CommandLine.hpp"
#include "passageMesh/policy/PolicyTrainer.hpp"
#include "passageMesh/policy/ToyEnvironment.hpp"

using namespace passageMesh;

int main(int argc, char* argv[]) {
  // A bad argument ends in one line on stderr and exit code 1.
  return runUtility("policyLearnerBenchmark", [&] {
    PolicyTrainOptions options;
    options.episodes = argc > 1 ? std::atol(argv[1]) : 20000;
    std::string hidden = argc > 2 ? argv[2] : "64,64";
    options.hidden.clear();
    std::istringstream widths(hidden);
    for (std::string w; std::getline(widths, w, ',');) options.hidden.push_back(std::stoi(w));
    // LEARNING_RATE: one rate for both networks, or ACTOR/CRITIC
    const std::string rates = argc > 3 ? argv[3] : "1e-3";
    const double rate = std::stod(rates);
    const auto slash = rates.find('/');
    options.learningRates = {rate, slash == std::string::npos ? rate : std::stod(rates.substr(slash + 1))};
    options.seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
    if (argc > 5) options.criticUpdatesPerEpisode = std::atoi(argv[5]);
    if (argc > 6) options.actorUpdateEvery = std::atoi(argv[6]);
    if (argc > 7) options.minibatch = std::atoi(argv[7]);
    if (argc > 8) options.criticModel = criticModelNamed(argv[8]);
    const double cliff = argc > 9 ? std::atof(argv[9]) : std::numeric_limits<double>::infinity();
    if (argc > 10) {
      options.noiseStartSigma = std::atof(argv[10]);
      options.noiseAmplitude = options.noiseStartSigma / 3;
    }
    if (argc > 11) options.validityBarrier = std::atof(argv[11]);
    options.validationPassages = 0;
    options.threads = 1;

    const ToyEnvironment toy(24, 8, 7, cliff);
    ThreadRollouts rollouts(1);
    PolicyTrainer trainer(options, toy, rollouts);
    std::printf("toy problem 24 -> 8, hidden %s, learning rates %s, seed %llu, critic updates %d per "
                "episode, actor every %d, minibatch %d, critic %s (barrier %g), cliff %g\n", hidden.c_str(), rates.c_str(),
                static_cast<unsigned long long>(options.seed), options.criticUpdatesPerEpisode,
                options.actorUpdateEvery, options.minibatch, nameOf(options.criticModel).c_str(), options.validityBarrier, cliff);
    const auto start = std::chrono::steady_clock::now();
    long next = options.episodes / 10;
    PolicyTrainer::Events events;
    events.afterBatch = [&](const PolicyTrainer& t) {
      if (t.episode() < next && t.episode() < options.episodes) return;
      next += options.episodes / 10;
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("episode %7ld  RMS action error %.5f  mean reward (last %ld) %.5f  %.3f ms/episode\n",
                  t.episode(), toy.actionError(t.learner(), 99, 1000), options.logEvery,
                  t.learningCurve().empty() ? 0.0 : t.learningCurve().back().meanReward,
                  1e3 * s / static_cast<double>(t.episode()));
      std::fflush(stdout);
    };
    trainer.run(nullptr, events);
    return 0;
  });
}
