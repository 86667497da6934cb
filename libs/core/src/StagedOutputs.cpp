#include "passageMesh/core/StagedOutputs.hpp"

#include <unistd.h>

#include <atomic>
#include <stdexcept>
#include <string>

#include "passageMesh/core/AtomicFile.hpp"

namespace passageMesh {

namespace fs = std::filesystem;

namespace {

// A name beside `target` that no other process, and no other staging in this one, uses.
fs::path besides(const fs::path& target, const std::string& tag) {
  static std::atomic<long> stagings{0};
  return target.string() + "." + tag + std::to_string(static_cast<long>(::getpid())) + "." +
         std::to_string(stagings++);
}

}  // namespace

StagedOutputs::~StagedOutputs() {
  std::error_code ignored;
  for (const Entry& e : entries_) fs::remove_all(e.temporary, ignored);
}

fs::path StagedOutputs::stage(const fs::path& target, bool directory) {
  for (const Entry& e : entries_)
    if (e.target == target) throw std::runtime_error(target.string() + ": staged twice");
  if (fs::exists(target) && fs::is_directory(target) != directory)
    throw std::runtime_error(target.string() + ": cannot replace, it is " +
                             (directory ? "not a directory" : "a directory"));
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  const fs::path temporary = besides(target, "tmp");
  fs::remove_all(temporary, ec);
  if (directory && !fs::create_directory(temporary, ec))
    throw std::runtime_error(target.string() + ": cannot write (" +
                             (ec ? ec.message() : std::string("cannot make ") + temporary.string()) + ")");
  entries_.push_back({target, temporary, directory});
  return temporary;
}

void StagedOutputs::writeFile(const fs::path& target, const std::string& content) {
  write(fileWithContent(target, content));
}

void StagedOutputs::write(const FileWriter& writer) { writer.write(stage(writer.file, false)); }

void StagedOutputs::commit() {
  for (const Entry& e : entries_)
    if (!fs::exists(e.temporary)) throw std::runtime_error(e.target.string() + ": was not written");
  for (const Entry& e : entries_) {
    std::error_code ec;
    if (e.directory && fs::exists(e.target)) {
      const fs::path old = besides(e.target, "old");
      fs::remove_all(old, ec);
      fs::rename(e.target, old, ec);
      if (!ec) fs::rename(e.temporary, e.target, ec);
      if (ec) {
        std::error_code ignored;
        if (!fs::exists(e.target)) fs::rename(old, e.target, ignored);
        throw std::runtime_error(e.target.string() + ": cannot replace (" + ec.message() + ")");
      }
      fs::remove_all(old, ec);
    } else {
      fs::rename(e.temporary, e.target, ec);
      if (ec) throw std::runtime_error(e.target.string() + ": cannot replace (" + ec.message() + ")");
    }
  }
  entries_.clear();
}

}  // namespace passageMesh
