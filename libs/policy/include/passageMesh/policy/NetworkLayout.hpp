#pragma once
// The shape of the actor and critic networks (method.md section 6; the paper's hidden
// layers are 512-256-256-128 with Leaky ReLU).
#include <string>
#include <vector>

namespace passageMesh {

struct NetworkLayout {
  int stateSize = 0;
  int actionSize = 0;
  std::vector<int> hidden{512, 256, 256, 128};
  double leakySlope = 0.01;  // Leaky ReLU's negative slope (PyTorch's default)

  std::string hiddenText() const;  // "512 256 256 128"
  bool operator==(const NetworkLayout&) const = default;
};

}  // namespace passageMesh
