// GnuplotRun: pictures appear together once gnuplot has drawn them all, or not at all.
// Uses the gnuplot on the PATH (Allwmake installs it); skipped without one.
#include "passageMesh/core/GnuplotRun.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "../TestFiles.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;
namespace fs = std::filesystem;

namespace {

bool haveGnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

long entriesIn(const fs::path& dir) {
  return std::distance(fs::directory_iterator(dir), fs::directory_iterator());
}

}  // namespace

TEST(GnuplotRun, DrawsEveryPictureAndLeavesNoTemporary) {
  if (!haveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const fs::path dir = tempFolder("gnuplotDraws");
  fs::remove_all(dir);
  {
    GnuplotRun run;
    std::string script = gnuplotPngTerminal(200, 150);
    script += run.output(dir / "a.png") + "plot " + run.dataFile("0 0\n1 1\n") + " with lines\n";
    script += run.output(dir / "sub" / "b.png") + "plot sin(x)\n";
    run.run(script);
  }
  for (const char* png : {"a.png", "sub/b.png"}) {
    ASSERT_TRUE(fs::is_regular_file(dir / png)) << png;
    EXPECT_EQ(readText(dir / png).substr(1, 3), "PNG") << png;
  }
  EXPECT_EQ(entriesIn(dir), 2);  // a.png and sub/, nothing staged left beside them
  EXPECT_EQ(entriesIn(dir / "sub"), 1);
}

TEST(GnuplotRun, AFailedScriptLeavesEveryPictureAsItWas) {
  if (!haveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const fs::path dir = tempFolder("gnuplotFails");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "a.png") << "old a";
  {
    GnuplotRun run;
    std::string script = gnuplotPngTerminal(200, 150);
    script += run.output(dir / "a.png") + "plot sin(x)\n";
    script += run.output(dir / "b.png") + "plot thisIsNotAFunction(x)\n";
    try {
      run.run(script);
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("gnuplot failed (", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;  // one line
    }
  }
  EXPECT_EQ(readText(dir / "a.png"), "old a");  // the first picture was drawn, and not moved in
  EXPECT_FALSE(fs::exists(dir / "b.png"));
  EXPECT_EQ(entriesIn(dir), 1);  // no temporary left
}

TEST(GnuplotRun, NamesAMissingProgramAndAnUnwritableFolder) {
  try {
    GnuplotRun run("passageMeshNoSuchGnuplot");
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("passageMeshNoSuchGnuplot is not installed"), std::string::npos) << e.what();
  }
  if (!haveGnuplot()) GTEST_SKIP() << "no gnuplot";
  const fs::path dir = tempFolder("gnuplotUnwritable");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "notAFolder") << "x";
  GnuplotRun run;
  try {
    run.output(dir / "notAFolder" / "a.png");
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "notAFolder" / "a.png").string() + ": cannot write file ("),
              std::string::npos)
        << e.what();
  }
}
