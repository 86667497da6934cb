#include "passageMesh/core/InputError.hpp"

namespace passageMesh {

namespace {
std::string locate(const std::string& file, int line, const std::string& what) {
  std::string where = file;
  if (line > 0) where.append(":").append(std::to_string(line));
  return where.append(": ").append(what);
}
}  // namespace

InputError::InputError(const std::string& file, int line, const std::string& what)
    : std::runtime_error(locate(file, line, what)) {}

InputError::InputError(const std::string& what) : std::runtime_error(what) {}

}  // namespace passageMesh
