#pragma once
// The shape of the actor and critic networks (method.md section 6; the paper's hidden
// layers are 512-256-256-128 with Leaky ReLU).
#include <string>
#include <vector>

namespace passageMesh {

// What the critic predicts. `reward`: one network fitted to the reward by mean squared
// error (the paper's). `validityAndQuality`: two networks, the probability p(s, a) that the
// mesh is valid (logistic loss on every episode) and its quality q(s, a) if valid (squared
// error on the valid episodes only); the expected reward p q + (1 - p)(-1) is what the
// actor climbs. It keeps the -1 of invalid meshes out of the quality fit, whose
// differences near the optimum are a hundred times smaller (docs/policy.md).
// `validityAndBoundedQuality`: the same with q = sigmoid(output), in (0, 1) as the Q of a
// valid mesh is: fitted on valid meshes only, an unbounded q can promise the actor more
// than any mesh gives where the data are few (docs/policy.md).
enum class CriticModel { reward, validityAndQuality, validityAndBoundedQuality };

// Whether the critic has the validity network p(s, a).
inline bool hasValidity(CriticModel m) { return m != CriticModel::reward; }

struct NetworkLayout {
  int stateSize = 0;
  int actionSize = 0;
  std::vector<int> hidden{512, 256, 256, 128};
  double leakySlope = 0.01;  // Leaky ReLU's negative slope (PyTorch's default)
  CriticModel critic = CriticModel::reward;  // the actor's layout does not depend on it

  std::string hiddenText() const;  // "512 256 256 128"
  bool operator==(const NetworkLayout&) const = default;
};

}  // namespace passageMesh
