#pragma once
// A persistent segmenter (the study's `segmenter: "worker: COMMAND"`): one
// process per study, started at its first request and kept for the next, so
// that a network is loaded once instead of once per run.
//
// The protocol, one line each way per run: the study writes
// "INPUT<TAB>OUTPUT\n" on the worker's stdin; the worker writes OUTPUT and
// answers "ok\n" on its stdout, or any other line to say why it could not
// (that run fails, the worker stays). Its stderr is forwarded to ours. A
// worker that exits or closes its stdout without answering, answers later
// than the timeout, or writes more than kMaxAnswerBytes without a line break
// fails that run, is killed (its process group) and is started again for the
// next. Closing its stdin at the end of the study asks it to exit; it is
// killed if it has not within 5 s.

#include <sys/types.h>

#include <cstddef>
#include <memory>
#include <string>

#include "occlusion/core/progress.hpp"

namespace occlusion::job {

inline constexpr const char* kWorkerPrefix = "worker:";

// The longest answer line: an answer is "ok" or a sentence, so a worker past
// this is printing on stdout what belongs on stderr, and reading it to its end
// could take a run's memory.
inline constexpr std::size_t kMaxAnswerBytes = 65536;

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
  bool has_exited() const;
  // Reads what its stdout holds now into pending_; false at its end.
  bool read_answers();
  // The answer when its stdout ended: it exited (waited for briefly) or
  // closed it and lives on (killed).
  WorkerAnswer ended_without_answer();

  pid_t pid_ = -1;
  int requests_fd_ = -1;  // our end of its stdin (a socket: send() without SIGPIPE)
  int answers_fd_ = -1;   // our end of its stdout (a pipe, non-blocking)
  int stderr_fd_ = -1;
  std::string command_;
  std::string pending_;  // stdout read past the last answer line
  std::string tail_;
  std::size_t starts_ = 0;
};

// An idle worker for a study's context; the process starts on first use.
std::shared_ptr<SegmenterWorker> idle_segmenter_worker();

}  // namespace occlusion::job
