#include "passageMesh/core/EtcFiles.hpp"

#include <cstdlib>

#include "passageMesh/core/InputError.hpp"

namespace passageMesh {

std::filesystem::path etcDirectory() {
  if (const char* env = std::getenv("PASSAGEMESH_ETC"); env && *env) return env;
  return PASSAGEMESH_ETC_DIR;
}

std::filesystem::path findEtcFile(const std::string& name) {
  const auto file = etcDirectory() / name;
  if (!std::filesystem::is_regular_file(file))
    throw InputError(file.string(), 0, "suite data file not found (set PASSAGEMESH_ETC?)");
  return file;
}

}  // namespace passageMesh
