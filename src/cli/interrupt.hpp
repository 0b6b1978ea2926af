#pragma once
// Ctrl-C (SIGINT) and a scheduler's SIGTERM as a cancel request: the job
// stops at its next check, leaving its outputs whole (the study keeps every
// finished row), instead of dying mid-write with its child processes orphaned.

#include <atomic>

namespace occlusion::cli {

// Installs the handlers (once) and returns the flag they set. A second
// signal of the same kind ends the process at once, as without the handler.
const std::atomic<bool>* cancel_on_interrupt();

}  // namespace occlusion::cli
