#pragma once
// Running a utility on a throw-away case directory and reading what it printed.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <thread>
#include <vector>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../TestFiles.hpp"

extern char** environ;

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

// The same with the files it writes limited to `kilobytes` (ulimit -f) and SIGXFSZ
// ignored, so that a write past the limit fails (EFBIG) as on a full disk. `arguments` may
// hold single quotes, not double ones.
inline RunResult runWithFileSizeLimit(const std::string& executable, const std::string& arguments,
                                      const std::filesystem::path& outputDir, int kilobytes) {
  return runCommand("/bin/sh", "-c \"trap '' XFSZ; ulimit -f " + std::to_string(kilobytes) + "; exec '" + executable +
                                   "' " + arguments + "\"", outputDir);
}

inline RunResult runTool(const std::string& executable, const std::filesystem::path& caseDir,
                         const std::string& arguments = "") {
  return runCommand(executable, "-case '" + caseDir.string() + "' " + arguments, caseDir);
}

// Starts `executable -case DIR ARGUMENTS...` in the background with its output in files; returns its process id.
inline pid_t startInBackground(const std::string& executable, const std::filesystem::path& dir,
                               const std::vector<std::string>& arguments) {
  std::vector<std::string> words{executable, "-case", dir.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, (dir / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, 2, (dir / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, executable.c_str(), &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  return failed ? -1 : pid;
}

inline bool waitForText(const std::filesystem::path& file, const std::string& text, std::chrono::seconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (readText(file).find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// waitpid's status, or kills the process and returns -1 when it does not end in time.
inline int waitForExit(pid_t pid, std::chrono::seconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return -1;
}

// Ctrl-C once a run is under way: waits (up to 60 s) for `text` in `file` (its stdout.txt
// or stderr.txt), sends SIGINT and expects the process to exit by itself within 60 s with
// exit code 130, the suite's code for a run stopped early that wrote what it had.
inline void expectInterruptedWith130(pid_t pid, const std::filesystem::path& file, const std::string& text) {
  const bool started = waitForText(file, text, std::chrono::seconds(60));
  kill(pid, SIGINT);
  const int status = waitForExit(pid, std::chrono::seconds(60));
  ASSERT_TRUE(started) << readText(file);
  ASSERT_NE(status, -1) << "no exit within 60 s of SIGINT";
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 130);
}

}  // namespace passageMesh::testData
