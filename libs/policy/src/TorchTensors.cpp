#include "TorchTensors.hpp"

#include <unistd.h>

#include <stdexcept>
#include <string>

namespace passageMesh {

void saveArchiveAtomically(torch::serialize::OutputArchive& archive,
                           const std::filesystem::path& file) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  // A name of this process's own, so that two writers never share a temporary.
  const std::filesystem::path temporary = file.string() + ".writing." + std::to_string(::getpid());
  try {
    archive.save_to(temporary.string());
    std::filesystem::rename(temporary, file);
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    std::string what = e.what();  // LibTorch's messages carry a backtrace after the first line
    throw std::runtime_error("cannot write " + file.string() + ": " + what.substr(0, what.find('\n')));
  }
}

}  // namespace passageMesh
