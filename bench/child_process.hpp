#pragma once
// Runs a program to completion and measures it from the outside: wall time
// from fork to reaping, and the kernel's peak resident set size.

#include <cstddef>
#include <string>
#include <vector>

namespace occlusion::bench {

struct ChildResult {
  int exit_code = -1;  // the exit status, or 128 + signal number if killed
  double wall_seconds = 0.0;
  std::size_t peak_rss_bytes = 0;  // ru_maxrss from wait4
  std::string out;                 // captured stdout
  std::string err;                 // captured stderr
};

// fork + execv of argv[0] (a path) with argv. Output goes through the files
// `capture_prefix`.out/.err rather than pipes, so a chatty child never blocks
// and the wall time is not stretched by our reading.
//
// Linux carries the pre-exec high-water mark into ru_maxrss, and a forked
// child starts with its parent's resident pages: the figure is
// max(caller's RSS at fork, child's own peak). Call this while the caller is small.
// Throws std::runtime_error if the capture files or the fork fail; a failed
// exec shows as exit code 127.
ChildResult run_measured(const std::vector<std::string>& argv, const std::string& capture_prefix);

}  // namespace occlusion::bench
