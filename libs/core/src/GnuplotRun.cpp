#include "passageMesh/core/GnuplotRun.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "passageMesh/core/AtomicFile.hpp"

namespace passageMesh {

namespace {

namespace fs = std::filesystem;

// A path as a single-quoted word for the shell.
std::string shellQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool onPath(const std::string& program) {
  if (program.find('/') != std::string::npos) return ::access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

// gnuplot's first message line that says something (it underlines errors with '^').
std::string firstLine(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t^") != std::string::npos) return line;
  return "";
}

}  // namespace

std::string gnuplotQuoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

std::string gnuplotPngTerminal(int width, int height) {
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height);
  return "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
         "  set terminal pngcairo enhanced font 'sans,11'" + size + "\n"
         "} else {\n"
         "  set terminal png enhanced" + size + "\n"
         "}\n";
}

GnuplotRun::GnuplotRun(std::string program) : program_(std::move(program)) {
  if (!onPath(program_))
    throw std::runtime_error(program_ + " is not installed (Debian package gnuplot-nox)");
  std::string pattern = (fs::temp_directory_path() / "passageMeshGnuplot.XXXXXX").string();
  if (!::mkdtemp(pattern.data()))
    throw std::runtime_error("cannot make a temporary folder under " +
                             fs::temp_directory_path().string());
  folder_ = pattern;
}

GnuplotRun::~GnuplotRun() {
  std::error_code ignored;
  fs::remove_all(folder_, ignored);  // pictures_ removes the pictures not moved into place
}

std::string GnuplotRun::output(const fs::path& png) {
  const fs::path temporary = pictures_.stage(png, false);
  // A folder that cannot take the picture is said here, with the reason; gnuplot's own
  // message would only quote its `set output` line.
  errno = 0;
  if (!std::ofstream(temporary))
    throw std::runtime_error(png.string() + ": cannot write file (" + fileErrorReason("cannot create it") + ")");
  std::error_code ignored;
  fs::remove(temporary, ignored);
  temporaries_.push_back(temporary);
  return "set output " + gnuplotQuoted(temporary.string()) + "\n";
}

std::string GnuplotRun::dataFile(const std::string& content) {
  const fs::path file = folder_ / ("data" + std::to_string(dataFiles_++) + ".dat");
  writeFileAtomically(file, content);
  return gnuplotQuoted(file.string());
}

void GnuplotRun::run(const std::string& script) {
  const fs::path scriptFile = folder_ / "script.gp", errors = folder_ / "errors.txt";
  // `unset output` closes the last picture before gnuplot exits.
  writeFileAtomically(scriptFile, script + "\nunset output\n");
  const int status = std::system((shellQuoted(program_) + " " + shellQuoted(scriptFile.string()) +
                                  " 2>" + shellQuoted(errors.string())).c_str());
  bool drawn = status == 0;
  for (const auto& picture : temporaries_) drawn = drawn && fs::is_regular_file(picture);
  if (!drawn) {
    const std::string why = firstLine(errors);
    throw std::runtime_error("gnuplot failed" + (why.empty() ? std::string() : " (" + why + ")"));
  }
  pictures_.commit();
  temporaries_.clear();
}

}  // namespace passageMesh
