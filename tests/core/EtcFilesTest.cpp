// The suite's data files: $PASSAGEMESH_ETC first, else the source tree's etc/; a missing
// file is an InputError naming the path it looked for.
#include "passageMesh/core/EtcFiles.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include "../TestFiles.hpp"
#include "passageMesh/core/InputError.hpp"

using namespace passageMesh;
namespace fs = std::filesystem;

namespace {

// Sets PASSAGEMESH_ETC for the scope of a test and puts back what was there.
class EtcOverride {
 public:
  explicit EtcOverride(const std::string& dir) {
    if (const char* old = std::getenv("PASSAGEMESH_ETC")) old_ = old;
    ::setenv("PASSAGEMESH_ETC", dir.c_str(), 1);
  }
  ~EtcOverride() {
    if (old_) ::setenv("PASSAGEMESH_ETC", old_->c_str(), 1);
    else ::unsetenv("PASSAGEMESH_ETC");
  }

 private:
  std::optional<std::string> old_;
};

}  // namespace

TEST(EtcFiles, TheEnvironmentsFolderComesFirstAndAMissingFileIsNamed) {
  const fs::path dir = testData::tempFolder("etcOverride");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "meshDictDefaults.xml") << "<meshDict/>";
  {
    const EtcOverride etc(dir.string());
    EXPECT_EQ(etcDirectory(), dir);
    EXPECT_EQ(findEtcFile("meshDictDefaults.xml"), dir / "meshDictDefaults.xml");
    try {
      findEtcFile("bladeParameterRange.xml");
      ADD_FAILURE() << "no exception";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find((dir / "bladeParameterRange.xml").string()), std::string::npos)
          << e.what();
    }
  }
  // Without the variable: the source tree's etc/, which holds the shipped files.
  const EtcOverride none("");
  EXPECT_TRUE(fs::is_regular_file(findEtcFile("meshDictDefaults.xml")));
  EXPECT_EQ(findEtcFile("meshDictDefaults.xml").parent_path().filename(), "etc");
}
