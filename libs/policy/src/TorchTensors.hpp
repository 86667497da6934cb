#pragma once
// Conversions between the project's batches (Eigen, double) and LibTorch tensors (float32),
// and atomic saving of a module. Private to libs/policy.
#include <torch/torch.h>

#include <filesystem>

#include "passageMesh/policy/ReplayBuffer.hpp"

namespace passageMesh {

inline torch::Tensor tensorOf(const PolicyBatch& batch) {
  return torch::from_blob(const_cast<double*>(batch.data()), {batch.rows(), batch.cols()},
                          torch::kFloat64)
      .to(torch::kFloat32);
}

inline PolicyBatch batchOf(const torch::Tensor& tensor) {
  const torch::Tensor t = tensor.to(torch::kFloat64).contiguous();
  const long rows = t.size(0), cols = t.dim() > 1 ? t.size(1) : 1;
  return Eigen::Map<const PolicyBatch>(t.data_ptr<double>(), rows, cols);
}

// An archive written to a temporary file beside `file`, then renamed over it.
void saveArchiveAtomically(torch::serialize::OutputArchive& archive,
                           const std::filesystem::path& file);

inline void saveModuleAtomically(const torch::nn::Module& module, const std::filesystem::path& file) {
  torch::serialize::OutputArchive archive;
  module.save(archive);
  saveArchiveAtomically(archive, file);
}

}  // namespace passageMesh
