#pragma once
// Several outputs, files or whole directories (an OpenFOAM polyMesh), that appear
// together or not at all (writeFilesAtomically, AtomicFile.hpp, is this for files): each
// is written to a temporary beside its target, and only when every one is complete are
// they moved into place. A failure before commit() leaves every target as it was; the
// destructor removes what was staged and not committed.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "passageMesh/core/AtomicFile.hpp"

namespace passageMesh {

class StagedOutputs {
 public:
  StagedOutputs() = default;
  ~StagedOutputs();
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  // The temporary path to write `target` into (beside it: same file system, so the move
  // is a rename; a name of its own, so two stagings of one target never share it); creates
  // the target's parent directory. Throws std::runtime_error when it cannot, when the target
  // exists as a different kind (directory versus file) than `directory` says, or when this
  // object has staged it already.
  std::filesystem::path stage(const std::filesystem::path& target, bool directory);

  // Stages the file `target` and writes `content` to its temporary; a failure names
  // `target` and the reason.
  void writeFile(const std::filesystem::path& target, const std::string& content);

  // Stages `writer.file` and lets the writer write its temporary (a file a library writes
  // itself, such as CGNS); the writer's errors name `writer.file`.
  void write(const FileWriter& writer);

  // Moves every staged output over its target. A directory target is replaced whole: the
  // old one is renamed aside, the new one renamed in, the old one removed. Throws
  // std::runtime_error naming the target when a staged output is missing or a move fails.
  void commit();

 private:
  struct Entry {
    std::filesystem::path target, temporary;
    bool directory = false;
  };
  std::vector<Entry> entries_;
};

}  // namespace passageMesh
