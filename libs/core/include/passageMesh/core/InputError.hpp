#pragma once
// The one exception type for bad user input: a file that is missing, malformed or out of
// range. Its message is a single line that names the file (and the line when known), so a
// utility can print it as it is and exit non-zero.
#include <stdexcept>
#include <string>

namespace passageMesh {

class InputError : public std::runtime_error {
 public:
  // "FILE:LINE: WHAT" (LINE <= 0 leaves the line out).
  InputError(const std::string& file, int line, const std::string& what);
  explicit InputError(const std::string& what);
};

}  // namespace passageMesh
