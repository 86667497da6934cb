#include "passageMesh/core/ParallelFor.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

using namespace passageMesh;

TEST(ParallelFor, RunsEveryIndexOnceAndRethrowsAfterAllThreadsEnd) {
  std::vector<std::atomic<int>> runs(57);
  parallelFor(57, 3, [&](int i) { ++runs[static_cast<std::size_t>(i)]; });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
  std::atomic<int> done{0};
  EXPECT_THROW(parallelFor(20, 2,
                           [&](int i) {
                             ++done;
                             if (i == 3) throw std::runtime_error("index 3");
                           }),
               std::runtime_error);
  EXPECT_EQ(done.load(), 20);
}

TEST(RunBeside, RunsTheWorkOnAnotherThreadAndMeanwhileOnThisOne) {
  const std::thread::id caller = std::this_thread::get_id();
  std::thread::id workThread, meanwhileThread;
  std::atomic<bool> workDone{false};
  runBeside(
      [&] {
        workThread = std::this_thread::get_id();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        workDone = true;
      },
      [&] { meanwhileThread = std::this_thread::get_id(); });
  EXPECT_TRUE(workDone.load());  // waited for
  EXPECT_EQ(meanwhileThread, caller);
  EXPECT_NE(workThread, caller);
}

TEST(RunBeside, RethrowsMeanwhilesExceptionFirstAndWaitsForTheWorkEitherWay) {
  const auto message = [](const std::function<void()>& work, const std::function<void()>& meanwhile) {
    try {
      runBeside(work, meanwhile);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("none");
  };
  std::atomic<bool> workDone{false};
  const auto slowWork = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    workDone = true;
    throw std::runtime_error("work");
  };
  EXPECT_EQ(message(slowWork, [] { throw std::runtime_error("meanwhile"); }), "meanwhile");
  EXPECT_TRUE(workDone.load());
  EXPECT_EQ(message(slowWork, [] {}), "work");
  EXPECT_EQ(message([] {}, [] {}), "none");
}
