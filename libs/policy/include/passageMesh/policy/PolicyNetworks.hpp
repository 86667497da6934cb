#pragma once
// The actor and critic networks as LibTorch modules (method.md section 6): fully connected
// layers with Leaky ReLU between them, tanh on the actor's output. This header includes
// <torch/torch.h> (about 25 s to compile): only the policy library's sources and its tests
// include it; the rest of the project sees ActorCritic.hpp and Policy.hpp.
//
// Parameter names, as Python's torch.jit.load shows them: layers.0.weight, layers.0.bias,
// layers.2.weight, ... (the odd indices are the activations, which have no parameters).
#include <torch/torch.h>

#include <string>
#include <vector>

#include "passageMesh/policy/NetworkLayout.hpp"

namespace passageMesh {

// A fully connected network: input, hidden layers, output; tanh on the output if asked.
class FullyConnectedImpl : public torch::nn::Module {
 public:
  FullyConnectedImpl(int inputs, const std::vector<int>& hidden, int outputs, double leakySlope,
                     bool tanhOutput);
  torch::Tensor forward(torch::Tensor x);
  // The output before the final tanh (the same as forward without one).
  torch::Tensor beforeOutput(torch::Tensor x);
  // Makes the output start near `output` for every input: the last layer's weights are
  // scaled by `weightScale` and its bias set so that the output is `output` at zero
  // weights (through atanh for a tanh output; values clipped to +-0.95 there).
  void startAt(const std::vector<double>& output, double weightScale);
  // Copies `other`'s weights: the same inputs and hidden layers, as many or fewer outputs;
  // outputs it lacks get zero weights and bias (0 after the tanh). Throws
  // std::invalid_argument where the layouts differ otherwise.
  void startFrom(FullyConnectedImpl& other);
  // After a backward pass: drops the gradients of every layer but the output layer (an
  // optimiser then leaves them as they are) and zeroes the output layer's gradient rows of
  // the outputs not listed, so that a step moves only the listed outputs' rows.
  void keepOutputGradients(const std::vector<int>& outputs);
  // Zeroes the listed outputs' rows of the output layer's weights, so that each of them is
  // its bias (through the tanh) for every input.
  void makeOutputsConstant(const std::vector<int>& outputs);
  // After a backward pass: zeroes the output layer's gradient rows of the listed outputs (an
  // Adam step then leaves those rows as they are, bit for bit, while its moments for them
  // stay zero), every other weight keeping its gradient.
  void dropOutputGradients(const std::vector<int>& outputs);
  // The name of the first weight or bias holding NaN or infinity ("layers.0.weight"), or
  // "" when every one is finite: a diverged run or a corrupt file, refused where loaded.
  std::string nonFiniteParameter() const;

 private:
  torch::nn::Sequential layers_;
};
TORCH_MODULE(FullyConnected);

// "the <networkName>'s layers.2.weight holds NaN or infinity" for the first weight or bias
// of `network` that does, or "" when every one is finite: the one wording of that refusal
// (loading a policy or checkpoint, writing one, a diverged learner).
std::string nonFiniteWeightProblem(const FullyConnected& network, const std::string& networkName);

// pi(s): state -> action in [-1, 1].
FullyConnected makeActor(const NetworkLayout& layout);
// Q(s, a): the concatenated state and action -> expected reward.
FullyConnected makeCritic(const NetworkLayout& layout);

}  // namespace passageMesh
