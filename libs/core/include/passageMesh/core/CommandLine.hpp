#pragma once
// The command line every utility shares, OpenFOAM-style: `-case DIR` (default `.`,
// `--case` also accepted), `-help`, `-version`, plus the utility's own options. Single-dash
// long options are accepted ("-case" and "--case" mean the same).
#include <boost/program_options.hpp>
#include <filesystem>
#include <functional>
#include <string>

namespace passageMesh {

class CommandLine {
 public:
  CommandLine(std::string utilityName, std::string purpose);

  // The utility adds its own options here before parse().
  boost::program_options::options_description_easy_init addOptions();

  // Returns false when -help or -version was printed and the utility should exit 0.
  // Throws InputError on an unknown or malformed option.
  bool parse(int argc, const char* const argv[]);

  const std::filesystem::path& caseDir() const { return caseDir_; }
  const boost::program_options::variables_map& values() const { return values_; }
  const std::string& utilityName() const { return name_; }

 private:
  std::string name_;
  std::string purpose_;
  boost::program_options::options_description options_;
  boost::program_options::variables_map values_;
  std::filesystem::path caseDir_ = ".";
};

// Runs a utility's body and turns every failure into a one-line message on stderr,
// "UTILITY: error: WHAT", and exit code 1. The body returns the exit code. First it
// keeps freed memory for reuse (HeapRetention.hpp), as every utility repeats allocations.
int runUtility(const std::string& utilityName, const std::function<int()>& body);

const char* passageMeshVersion();

}  // namespace passageMesh
