#include "passageMesh/policy/PolicyNetworks.hpp"

namespace passageMesh {

FullyConnectedImpl::FullyConnectedImpl(int inputs, const std::vector<int>& hidden, int outputs,
                                       double leakySlope, bool tanhOutput) {
  int width = inputs;
  for (int h : hidden) {
    layers_->push_back(torch::nn::Linear(width, h));
    layers_->push_back(torch::nn::LeakyReLU(torch::nn::LeakyReLUOptions().negative_slope(leakySlope)));
    width = h;
  }
  layers_->push_back(torch::nn::Linear(width, outputs));
  if (tanhOutput) layers_->push_back(torch::nn::Tanh());
  register_module("layers", layers_);
}

torch::Tensor FullyConnectedImpl::forward(torch::Tensor x) { return layers_->forward(x); }

FullyConnected makeActor(const NetworkLayout& layout) {
  return FullyConnected(layout.stateSize, layout.hidden, layout.actionSize, layout.leakySlope, true);
}

FullyConnected makeCritic(const NetworkLayout& layout) {
  return FullyConnected(layout.stateSize + layout.actionSize, layout.hidden, 1, layout.leakySlope,
                        false);
}

}  // namespace passageMesh
