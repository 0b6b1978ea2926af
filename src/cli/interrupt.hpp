#pragma once
// Ctrl-C and SIGTERM (Slurm's scancel, a timeout) stop a run cleanly: the
// first one sets a cancel flag that the analysis checks between blocks, so the
// job unwinds, its output set removes its temporary files and the previous
// outputs stay as they were; the process then dies of the same signal, as its
// caller expects. A second signal kills at once.

#include <atomic>

namespace occlusion::cli {

// Installs the handlers (once) and returns the flag they set.
const std::atomic<bool>& interrupt_flag();

// If a signal set the flag, ends the process by that signal; else returns.
void reraise_interrupt();

}  // namespace occlusion::cli
