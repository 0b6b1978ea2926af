#pragma once
// A persistent segmenter (the study's `segmenter: "worker: COMMAND"`): one
// process per study, started at its first request and kept for the next, so
// that a network is loaded once instead of once per run.
//
// The protocol, one line each way per run: the study writes
// "INPUT<TAB>OUTPUT\n" on the worker's stdin; the worker writes OUTPUT and
// answers "ok\n" on its stdout, or any other line to say why it could not
// (that run fails, the worker stays). Its stderr is forwarded to ours. A
// worker that dies, or answers later than the timeout (killed then), fails
// that run and is started again for the next. Closing its stdin at the end
// of the study asks it to exit; it is killed if it has not within 5 s.

#include <sys/types.h>

#include <cstddef>
#include <memory>
#include <string>

#include "occlusion/core/progress.hpp"

namespace occlusion::job {

inline constexpr const char* kWorkerPrefix = "worker:";

// True for "worker: COMMAND"; `command` receives COMMAND, trimmed.
bool is_worker_segmenter(const std::string& segmenter, std::string* command = nullptr);

struct WorkerAnswer {
  bool ok = false;
  std::string failure;      // why not: the worker's answer, its death or the timeout
  std::string output_tail;  // the end of what it wrote on stderr since it started
};

class SegmenterWorker {
 public:
  SegmenterWorker() = default;
  SegmenterWorker(const SegmenterWorker&) = delete;
  SegmenterWorker& operator=(const SegmenterWorker&) = delete;
  ~SegmenterWorker();

  // Sends one request to `command`'s worker (started if none is running) and
  // waits for its answer. Throws Cancelled (the worker killed) on cancel,
  // std::runtime_error when no process can be started.
  WorkerAnswer request(const std::string& command, const std::string& input,
                       const std::string& output, double timeout_seconds, const Progress& progress);

  // How many processes this object has started: 1 for a study whose worker
  // never died.
  std::size_t starts() const { return starts_; }

 private:
  void start(const std::string& command);
  // Reaps the process (killing its group first when `kill`); returns a
  // description of how it ended.
  std::string stop(bool kill);
  void forward_stderr();

  pid_t pid_ = -1;
  int requests_fd_ = -1;  // our end of its stdin and stdout (a socket pair)
  int stderr_fd_ = -1;
  std::string command_;
  std::string pending_;  // stdout read past the last answer line
  std::string tail_;
  std::size_t starts_ = 0;
};

// An idle worker for a study's context; the process starts on first use.
std::shared_ptr<SegmenterWorker> idle_segmenter_worker();

}  // namespace occlusion::job
