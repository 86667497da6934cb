#pragma once
// Drawing PNG pictures with gnuplot (the program, run without a display) so that a
// reader never sees a half-drawn picture: data and script go to a private temporary
// folder, gnuplot draws each picture into a temporary beside its target, and only when
// gnuplot succeeded and every picture exists are they renamed into place together.
// Used by plotMesh's pictures and iterOptimize's convergence plot.
#include <filesystem>
#include <string>
#include <vector>

#include "passageMesh/core/StagedOutputs.hpp"

namespace passageMesh {

// A path as a single-quoted gnuplot string (a quote is written twice).
std::string gnuplotQuoted(const std::string& text);

// The gnuplot commands choosing the PNG terminal at `width` x `height` pixels: pngcairo
// (anti-aliased) when this gnuplot has it, else the plain png terminal.
std::string gnuplotPngTerminal(int width, int height);

class GnuplotRun {
 public:
  // `program` names gnuplot (tests point it elsewhere). Throws std::runtime_error when it
  // is not on the PATH or the temporary folder cannot be made.
  explicit GnuplotRun(std::string program = "gnuplot");
  ~GnuplotRun();  // removes the temporaries of a run that did not finish
  GnuplotRun(const GnuplotRun&) = delete;
  GnuplotRun& operator=(const GnuplotRun&) = delete;

  // A `set output` command for the picture `png`: gnuplot writes a temporary, renamed
  // over `png` by run().
  std::string output(const std::filesystem::path& png);

  // Writes `content` to a new file in the temporary folder; returns its name quoted for
  // the script.
  std::string dataFile(const std::string& content);

  // Runs gnuplot on `script`, then renames every picture into place. Throws
  // std::runtime_error with one line ("gnuplot failed (its first error line)") and leaves
  // every target as it was when gnuplot fails or a picture is missing.
  void run(const std::string& script);

 private:
  std::string program_;
  std::filesystem::path folder_;
  StagedOutputs pictures_;  // each picture's temporary beside it, moved into place by run()
  std::vector<std::filesystem::path> temporaries_;  // those temporaries, which gnuplot must write
  int dataFiles_ = 0;
};

}  // namespace passageMesh
