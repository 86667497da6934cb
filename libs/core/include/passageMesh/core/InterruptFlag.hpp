#pragma once
// Ctrl-C as a request to stop, for long runs that poll a flag (iterOptimize's optimiser):
// the first SIGINT only sets the flag, so the run can finish its batch and write what it
// has; a second SIGINT ends the process at once (the default action), for a user who will
// not wait for the batch under way. Files written atomically stay complete either way.
#include <atomic>

namespace passageMesh {

// Installs the SIGINT handler (again re-arms the first-press behaviour) and returns the
// flag it sets. Setting a lock-free std::atomic<bool> is safe in a signal handler.
const std::atomic<bool>& installInterruptFlag();

// The exit code of a tool that stopped early on Ctrl-C after writing what it had: 128 +
// SIGINT, as a shell reports it.
inline constexpr int interruptedExitCode = 130;

}  // namespace passageMesh
