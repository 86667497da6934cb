#include "passageMesh/core/StagedOutputs.hpp"
#include "passageMesh/core/AtomicFile.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

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

namespace {

std::string fileText(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// An empty test folder holding a.txt with "old a".
fs::path folderWithOldA(const std::string& name) {
  const fs::path dir = tempFolder(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "a.txt") << "old a";
  return dir;
}

}  // namespace

TEST(StagedOutputs, AFileWriterWritesItsTemporaryAndAFailureLeavesEveryTargetAsItWas) {
  const fs::path dir = folderWithOldA("stagedWriter");
  fs::path written;
  const FileWriter fine{dir / "a.txt", [&](const fs::path& temporary) {
                          written = temporary;
                          std::ofstream(temporary) << "new a";
                        }};
  const FileWriter failing{dir / "b.txt", [](const fs::path&) { throw std::runtime_error("b.txt: no room"); }};
  {
    StagedOutputs staged;
    staged.write(fine);
    EXPECT_NE(written, dir / "a.txt");  // the writer is given the temporary, not the target
    EXPECT_EQ(written.parent_path(), dir);
    EXPECT_THROW(staged.write(failing), std::runtime_error);
  }
  EXPECT_EQ(fileText(dir / "a.txt"), "old a");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  StagedOutputs staged;
  staged.write(fine);
  staged.commit();
  EXPECT_EQ(fileText(dir / "a.txt"), "new a");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// writeFilesAtomically with FileWriters (CGNS, VTK and a meshDict written together): a
// writer that fails leaves every target as it was and no temporary behind.
TEST(AtomicFile, AGroupOfFileWritersIsWrittenWholeOrNotAtAll) {
  const fs::path dir = folderWithOldA("atomicGroup");
  const FileWriter failing{dir / "c.txt", [](const fs::path&) { throw std::runtime_error("c.txt: no room"); }};
  EXPECT_THROW(writeFilesAtomically({fileWithContent(dir / "a.txt", "new a"), fileWithContent(dir / "sub" / "b.txt", "b"),
                                     failing}),
               std::runtime_error);
  EXPECT_EQ(fileText(dir / "a.txt"), "old a");
  EXPECT_FALSE(fs::exists(dir / "sub" / "b.txt"));
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    EXPECT_TRUE(entry.path() == dir / "a.txt" || entry.is_directory()) << entry.path();
  writeFilesAtomically({fileWithContent(dir / "a.txt", "new a"), fileWithContent(dir / "sub" / "b.txt", "b")});
  EXPECT_EQ(fileText(dir / "a.txt"), "new a");
  EXPECT_EQ(fileText(dir / "sub" / "b.txt"), "b");
}

TEST(StagedOutputs, OneTargetIsStagedOnceAndTwoStagingsNeverShareATemporary) {
  const fs::path dir = tempFolder("stagedTwice");
  fs::remove_all(dir);
  StagedOutputs first, second;
  const fs::path a = first.stage(dir / "out.txt", false);
  EXPECT_THROW(first.stage(dir / "out.txt", false), std::runtime_error);
  const fs::path b = second.stage(dir / "out.txt", false);
  EXPECT_NE(a, b);
  std::ofstream(a) << "first";
  std::ofstream(b) << "second";
  first.commit();
  second.commit();
  std::ifstream in(dir / "out.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), "second");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}
