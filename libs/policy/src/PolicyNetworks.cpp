#include "passageMesh/policy/PolicyNetworks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

torch::Tensor FullyConnectedImpl::beforeOutput(torch::Tensor x) {
  // The layers are Linear and LeakyReLU, with Tanh last on an actor (the constructor).
  for (std::size_t k = 0; k < layers_->size(); ++k) {
    if (auto* linear = layers_->ptr(k)->as<torch::nn::Linear>()) x = linear->forward(x);
    else if (auto* leaky = layers_->ptr(k)->as<torch::nn::LeakyReLU>()) x = leaky->forward(x);
  }
  return x;
}

void FullyConnectedImpl::startAt(const std::vector<double>& output, double weightScale) {
  torch::NoGradGuard noGrad;
  const bool tanhOutput = layers_->ptr(layers_->size() - 1)->as<torch::nn::Tanh>() != nullptr;
  auto* last = layers_->ptr(layers_->size() - (tanhOutput ? 2 : 1))->as<torch::nn::Linear>();
  last->weight.mul_(weightScale);
  for (std::size_t k = 0; k < output.size() && static_cast<long>(k) < last->bias.size(0); ++k) {
    const double v = tanhOutput ? std::atanh(std::clamp(output[k], -0.95, 0.95)) : output[k];
    last->bias[static_cast<long>(k)] = v;
  }
}

void FullyConnectedImpl::startFrom(FullyConnectedImpl& other) {
  torch::NoGradGuard noGrad;
  auto mine = parameters(), theirs = other.parameters();
  if (mine.size() != theirs.size()) throw std::invalid_argument("another number of layers");
  for (std::size_t k = 0; k < mine.size(); ++k) {
    torch::Tensor& to = mine[k];
    const torch::Tensor& from = theirs[k];
    const bool lastLayer = k + 2 >= mine.size();  // the output layer's weight and bias
    const bool fewerOutputs = lastLayer && from.dim() == to.dim() && from.size(0) < to.size(0) &&
                              (to.dim() == 1 || from.size(1) == to.size(1));
    if (from.sizes() == to.sizes()) {
      to.copy_(from);
    } else if (fewerOutputs) {
      to.zero_();
      to.narrow(0, 0, from.size(0)).copy_(from);
    } else {
      throw std::invalid_argument("layer weights of another shape");
    }
  }
}

void FullyConnectedImpl::keepOutputGradients(const std::vector<int>& outputs) {
  torch::NoGradGuard noGrad;
  auto all = parameters();
  const std::size_t outputLayer = all.size() - 2;  // its weight, then its bias
  for (std::size_t k = 0; k < outputLayer; ++k) all[k].mutable_grad() = torch::Tensor();
  std::vector<int> others;
  for (int o = 0; o < all[outputLayer].size(0); ++o)
    if (std::find(outputs.begin(), outputs.end(), o) == outputs.end()) others.push_back(o);
  dropOutputGradients(others);
}

void FullyConnectedImpl::makeOutputsConstant(const std::vector<int>& outputs) {
  torch::NoGradGuard noGrad;
  auto all = parameters();
  torch::Tensor& weight = all[all.size() - 2];  // the output layer's weight, then its bias
  for (int o : outputs) weight[o].zero_();
}

std::string FullyConnectedImpl::nonFiniteParameter() const {
  for (const auto& p : named_parameters())
    if (!torch::isfinite(p.value()).all().item<bool>()) return p.key();
  return "";
}

std::string nonFiniteWeightProblem(const FullyConnected& network, const std::string& networkName) {
  const std::string bad = network->nonFiniteParameter();
  return bad.empty() ? "" : "the " + networkName + "'s " + bad + " holds NaN or infinity";
}

void FullyConnectedImpl::dropOutputGradients(const std::vector<int>& outputs) {
  torch::NoGradGuard noGrad;
  auto all = parameters();
  for (std::size_t k = all.size() - 2; k < all.size(); ++k) {
    torch::Tensor& grad = all[k].mutable_grad();
    if (!grad.defined()) continue;
    for (int o : outputs) grad[o].zero_();
  }
}

FullyConnected makeActor(const NetworkLayout& layout) {
  return FullyConnected(layout.stateSize, layout.hidden, layout.actionSize, layout.leakySlope, true);
}

FullyConnected makeCritic(const NetworkLayout& layout) {
  return FullyConnected(layout.stateSize + layout.actionSize, layout.hidden, 1, layout.leakySlope,
                        false);
}

}  // namespace passageMesh
