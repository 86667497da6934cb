#include "TorchTensors.hpp"

#include <stdexcept>

namespace passageMesh {

void saveArchiveAtomically(torch::serialize::OutputArchive& archive,
                           const std::filesystem::path& file) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  const std::filesystem::path temporary = file.string() + ".writing";
  try {
    archive.save_to(temporary.string());
    std::filesystem::rename(temporary, file);
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error("cannot write " + file.string() + ": " + e.what());
  }
}

}  // namespace passageMesh
