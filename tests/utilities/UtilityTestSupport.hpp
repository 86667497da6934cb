#pragma once
// Running a utility on a throw-away case directory and reading what it printed.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../TestFiles.hpp"

namespace passageMesh::testData {

struct RunResult {
  int exitCode = -1;
  std::string out, err;
};

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeText(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A fresh, empty case directory under the system temporary directory.
inline std::filesystem::path freshCase(const std::string& name) {
  const auto dir = tempFolder("utilityCases") / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "constant");
  std::filesystem::create_directories(dir / "system");
  return dir;
}

// Runs `executable arguments`, its output captured in files under `outputDir`.
inline RunResult runCommand(const std::string& executable, const std::string& arguments,
                            const std::filesystem::path& outputDir) {
  const auto out = outputDir / "stdout.txt", err = outputDir / "stderr.txt";
  const std::string command = "'" + executable + "' " + arguments + " > '" + out.string() +
                              "' 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  RunResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readText(out);
  r.err = readText(err);
  return r;
}

inline RunResult runTool(const std::string& executable, const std::filesystem::path& caseDir,
                         const std::string& arguments = "") {
  return runCommand(executable, "-case '" + caseDir.string() + "' " + arguments, caseDir);
}

}  // namespace passageMesh::testData
