#pragma once
// Runs body(i) for i in [0, count) on up to `threads` threads (0 = all cores). Each index
// runs exactly once; results written by index keep a run deterministic whatever the
// thread count. The first exception thrown by a body is rethrown after all threads end.
#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace passageMesh {

// The threads a `threads` setting means: itself when positive, else all cores (at least 1).
inline int resolvedThreads(int threads) {
  return threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

template <typename Body>
void parallelFor(int count, int threads, const Body& body) {
  threads = resolvedThreads(threads);
  threads = std::min(threads, count);
  if (threads <= 1) {
    for (int i = 0; i < count; ++i) body(i);
    return;
  }
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto worker = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        body(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

// Runs `work` on a thread of its own and `meanwhile` on the calling one, then waits for
// both; rethrows meanwhile's exception, else work's. `meanwhile` stays on the calling thread
// because what it does may be bound to it (the policy trainer's learner: LibTorch set to
// one thread there, and MPI funnelled through the main thread).
inline void runBeside(const std::function<void()>& work, const std::function<void()>& meanwhile) {
  std::exception_ptr workFailure, meanwhileFailure;
  std::thread worker([&] {
    try {
      work();
    } catch (...) {
      workFailure = std::current_exception();
    }
  });
  try {
    meanwhile();
  } catch (...) {
    meanwhileFailure = std::current_exception();
  }
  worker.join();
  if (meanwhileFailure) std::rethrow_exception(meanwhileFailure);
  if (workFailure) std::rethrow_exception(workFailure);
}

}  // namespace passageMesh
