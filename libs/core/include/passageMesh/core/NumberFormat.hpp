#pragma once
// Numbers as text: in files (read back exactly) and in messages (short).
#include <string>

namespace passageMesh {

// 17 significant digits: enough to read back the same double (files, logs to compare).
std::string formatExact(double value);

// The shortest text that reads back as the same double (0.1, not 0.10000000000000001): for
// messages that state a value a reader compares with another, such as a range's bounds.
std::string formatShortest(double value);

// 6 significant digits, for messages about sizes and spans where rounding does not matter.
std::string formatRounded(double value);

}  // namespace passageMesh
