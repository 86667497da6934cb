#pragma once
// Finding the suite's data files (etc/): $PASSAGEMESH_ETC if set, else the etc/ directory
// of the source tree the tools were built from.
#include <filesystem>
#include <string>

namespace passageMesh {

std::filesystem::path etcDirectory();
// etcDirectory() / name; throws InputError when the file is not there.
std::filesystem::path findEtcFile(const std::string& name);

}  // namespace passageMesh
