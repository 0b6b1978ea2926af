#pragma once
// Running a command the user wrote (the study's --segmenter), internal to app/.

#include <cstddef>
#include <string>

#include "occlusion/core/progress.hpp"

namespace occlusion::job {

inline constexpr std::size_t kShellOutputTail = 2000;
inline constexpr std::size_t kForwardedPerCall = std::size_t{1} << 20;

// Forwards what a child wrote on `fd` since the last call to our stderr and
// keeps its last kShellOutputTail bytes in `tail`. `fd` must be non-blocking:
// returns when it is empty, or after about kForwardedPerCall bytes.
void forward_output(int fd, std::string& tail);

struct ShellResult {
  // The exit status; a command killed by signal s gives 128 + s, as the
  // shell reports it.
  int status = 0;
  bool timed_out = false;  // killed because it ran longer than the limit
  // The last bytes (at most kShellOutputTail) of what it wrote on stdout and
  // stderr: why it failed, for a report.
  std::string output_tail;
};

// Runs `command` with /bin/sh -c in its own process group, stdin from
// /dev/null and its stdout and stderr forwarded to our stderr (our stdout
// carries --json's one object) while their tail is kept. With
// timeout_seconds > 0 the whole group is killed once it has run that long.
// On cancel the whole group is killed and Cancelled thrown.
// std::runtime_error when no process can be started.
ShellResult run_shell_command(const std::string& command, const Progress& progress,
                              double timeout_seconds = 0.0);

}  // namespace occlusion::job
