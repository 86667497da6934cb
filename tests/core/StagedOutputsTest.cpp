#include "passageMesh/core/StagedOutputs.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <stdexcept>

#include "../TestFiles.hpp"

using namespace passageMesh;
using namespace passageMesh::testData;
namespace fs = std::filesystem;

TEST(StagedOutputs, DirectoryReplacedWholeOnlyOnCommit) {
  const fs::path dir = tempFolder("staged");
  fs::remove_all(dir);
  fs::create_directories(dir / "target");
  std::ofstream(dir / "target" / "old") << "old";
  {
    StagedOutputs staged;
    std::ofstream(staged.stage(dir / "target", true) / "new") << "new";
    std::ofstream(staged.stage(dir / "file.txt", false)) << "text";
    EXPECT_TRUE(fs::exists(dir / "target" / "old"));
    EXPECT_FALSE(fs::exists(dir / "file.txt"));
  }  // not committed: the temporaries are gone, the target unchanged
  EXPECT_TRUE(fs::exists(dir / "target" / "old"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  StagedOutputs staged;
  std::ofstream(staged.stage(dir / "target", true) / "new") << "new";
  staged.commit();
  EXPECT_TRUE(fs::exists(dir / "target" / "new"));
  EXPECT_FALSE(fs::exists(dir / "target" / "old"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  EXPECT_THROW(staged.stage(dir / "target", false), std::runtime_error);  // a directory, not a file
}
