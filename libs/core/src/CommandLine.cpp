#include "passageMesh/core/CommandLine.hpp"

#include <iostream>

#include "passageMesh/core/HeapRetention.hpp"
#include "passageMesh/core/InputError.hpp"

namespace passageMesh {

namespace po = boost::program_options;

const char* passageMeshVersion() { return PASSAGEMESH_VERSION; }

CommandLine::CommandLine(std::string utilityName, std::string purpose)
    : name_(std::move(utilityName)), purpose_(std::move(purpose)), options_("Options") {
  options_.add_options()
      ("case", po::value<std::string>()->default_value("."), "case directory")
      ("help", "print this help and exit")
      ("version", "print the version and exit");
}

po::options_description_easy_init CommandLine::addOptions() { return options_.add_options(); }

bool CommandLine::parse(int argc, const char* const argv[]) {
  try {
    // No abbreviations (-c is not -case) and no positional arguments: a stray word such
    // as a case name without -case must not silently run on the current directory.
    const auto style = (po::command_line_style::unix_style |
                        po::command_line_style::allow_long_disguise) &
                       ~po::command_line_style::allow_guessing;
    po::store(po::command_line_parser(argc, argv)
                  .options(options_)
                  .positional(po::positional_options_description())
                  .style(style)
                  .run(),
              values_);
    po::notify(values_);
  } catch (const po::error& e) {
    throw InputError(std::string("command line: ") + e.what() + " (see " + name_ + " -help)");
  }
  if (values_.count("help")) {
    std::cout << "Usage: " << name_ << " [OPTIONS]\n" << purpose_ << "\n\n"
              << "Single-dash long options are accepted (-case DIR == --case DIR).\n"
              << options_;
    return false;
  }
  if (values_.count("version")) {
    std::cout << name_ << " (passageMesh) " << passageMeshVersion() << "\n";
    return false;
  }
  caseDir_ = values_["case"].as<std::string>();
  if (!std::filesystem::is_directory(caseDir_))
    throw InputError(caseDir_.string(), 0,
                     std::filesystem::exists(caseDir_) ? "not a directory (expected the case directory)"
                                                       : "case directory not found");
  return true;
}

int runUtility(const std::string& utilityName, const std::function<int()>& body) {
  retainFreedHeapMemory();
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << utilityName << ": error: " << e.what() << std::endl;
  } catch (...) {
    std::cerr << utilityName << ": error: unknown failure" << std::endl;
  }
  return 1;
}

}  // namespace passageMesh
