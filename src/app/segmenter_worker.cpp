#include "segmenter_worker.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "shell_command.hpp"

namespace occlusion::job {

namespace {

constexpr double kExitGraceSeconds = 5.0;
// After its stdout ends, how long a worker may take to exit before it counts
// as one that closed its stdout and lives on: the pipe closes as a process
// exits, a moment before its status can be collected.
constexpr double kEndedGraceSeconds = 1.0;
// How often a wait looks at the cancel flag and the timeout when nothing
// arrives.
constexpr int kTickMilliseconds = 20;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string how_it_ended(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "ended";
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// The command in the background of a shell that keeps no copy of the
// worker's stdout: /bin/sh holds its own stdout while it waits for a
// foreground command, so a worker that closed its stdout would leave the
// pipe open through the shell and never be seen to. stdin is named again
// (<&4) because a background command's stdin is /dev/null otherwise; the
// shell exits with the command's status.
std::string shell_script(const std::string& command) {
  return "exec 3>&1 4<&0 1>&2 0</dev/null\n{\n" + command +
         "\n} <&4 >&3 3>&- 4<&- &\nexec 3>&- 4<&-\nwait $!\n";
}

}  // namespace

bool is_worker_segmenter(const std::string& segmenter, std::string* command) {
  const std::string prefix = kWorkerPrefix;
  if (segmenter.compare(0, prefix.size(), prefix) != 0) return false;
  if (command != nullptr) {
    const std::size_t first = segmenter.find_first_not_of(" \t", prefix.size());
    const std::size_t last = segmenter.find_last_not_of(" \t");
    *command = first == std::string::npos ? "" : segmenter.substr(first, last - first + 1);
  }
  return true;
}

SegmenterWorker::~SegmenterWorker() {
  if (pid_ < 0) return;
  // End of requests: a worker that reads to EOF exits by itself.
  ::shutdown(requests_fd_, SHUT_WR);
  const auto start = Clock::now();
  int status = 0;
  while (::waitpid(pid_, &status, WNOHANG) == 0) {
    forward_stderr();
    if (seconds_since(start) > kExitGraceSeconds) {
      ::kill(-pid_, SIGKILL);
      while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(kTickMilliseconds));
  }
  forward_stderr();
  close_fd(requests_fd_);
  close_fd(answers_fd_);
  close_fd(stderr_fd_);
  pid_ = -1;
}

void SegmenterWorker::start(const std::string& command) {
  int requests[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, requests) != 0) {
    throw std::runtime_error(std::string("cannot make a socket pair: ") + std::strerror(errno));
  }
  int answers[2];
  int errors[2];
  if (::pipe2(answers, O_CLOEXEC) != 0) {
    ::close(requests[0]);
    ::close(requests[1]);
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  if (::pipe2(errors, O_CLOEXEC) != 0) {
    for (const int fd : {requests[0], requests[1], answers[0], answers[1]}) ::close(fd);
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  const std::string script = shell_script(command);
  const pid_t pid = ::fork();
  if (pid < 0) {
    for (const int fd : {requests[0], requests[1], answers[0], answers[1], errors[0], errors[1]}) {
      ::close(fd);
    }
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // Only async-signal-safe calls until exec: the parent may have threads.
    // dup2 clears close-on-exec on the copies.
    ::setpgid(0, 0);
    ::dup2(requests[1], STDIN_FILENO);
    ::dup2(answers[1], STDOUT_FILENO);
    ::dup2(errors[1], STDERR_FILENO);
    ::execl("/bin/sh", "sh", "-c", script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  ::close(requests[1]);
  ::close(answers[1]);
  ::close(errors[1]);
  for (const int fd : {answers[0], errors[0]}) {
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  }
  pid_ = pid;
  requests_fd_ = requests[0];
  answers_fd_ = answers[0];
  stderr_fd_ = errors[0];
  command_ = command;
  pending_.clear();
  tail_.clear();
  ++starts_;
}

void SegmenterWorker::forward_stderr() {
  if (stderr_fd_ >= 0) forward_output(stderr_fd_, tail_);
}

bool SegmenterWorker::has_exited() const {
  // WNOWAIT: the process stays a zombie, so its group cannot be reused
  // before stop() kills what it left behind and collects it.
  siginfo_t info{};
  return ::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
         info.si_pid == pid_;
}

std::string SegmenterWorker::stop(bool kill) {
  if (pid_ < 0) return "not running";
  if (kill) ::kill(-pid_, SIGKILL);
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  forward_stderr();
  close_fd(requests_fd_);
  close_fd(answers_fd_);
  close_fd(stderr_fd_);
  pid_ = -1;
  return how_it_ended(status);
}

bool SegmenterWorker::read_answers() {
  // Large reads, bounded: a worker flooding its stdout is refused at
  // kMaxAnswerBytes, which takes a few reads.
  char buffer[65536];
  while (pending_.size() <= kMaxAnswerBytes) {
    const ssize_t got = ::read(answers_fd_, buffer, sizeof buffer);
    if (got > 0) {
      pending_.append(buffer, static_cast<std::size_t>(got));
      if (std::memchr(buffer, '\n', static_cast<std::size_t>(got)) != nullptr) return true;
      continue;
    }
    if (got < 0 && errno == EINTR) continue;
    // Empty for now (EAGAIN), or its end: every copy of its stdout closed.
    return got < 0;
  }
  return true;
}

WorkerAnswer SegmenterWorker::ended_without_answer() {
  const auto start = Clock::now();
  while (!has_exited() && seconds_since(start) < kEndedGraceSeconds) {
    forward_stderr();
    std::this_thread::sleep_for(std::chrono::milliseconds(kTickMilliseconds));
  }
  WorkerAnswer answer;
  if (has_exited()) {
    answer.failure = "the segmenter worker ended (" + stop(true) + ") without answering";
  } else {
    stop(true);
    answer.failure =
        "the segmenter worker closed its stdout without answering and was killed (it was still "
        "running; answers come on stdout, one line per run); the next run starts it again";
  }
  answer.output_tail = tail_;
  return answer;
}

WorkerAnswer SegmenterWorker::request(const std::string& command, const std::string& input,
                                      const std::string& output, double timeout_seconds,
                                      const Progress& progress) {
  progress.check_cancel();
  WorkerAnswer answer;
  for (const std::string* path : {&input, &output}) {
    if (path->find_first_of("\t\n") != std::string::npos) {
      answer.failure = "the path '" + *path +
                       "' has a tab or a line break, which the worker protocol cannot carry "
                       "(choose an out folder without them)";
      return answer;
    }
  }
  if (pid_ >= 0 && command != command_) stop(true);
  if (pid_ < 0) start(command);
  const std::string line = input + "\t" + output + "\n";
  std::size_t sent = 0;
  while (sent < line.size()) {
    const ssize_t n = ::send(requests_fd_, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      answer.failure = "the segmenter worker is gone (" + stop(true) + ") before it read the run";
      answer.output_tail = tail_;
      return answer;
    }
    sent += static_cast<std::size_t>(n);
  }
  const auto start = Clock::now();
  std::size_t searched = 0;  // pending_ before this holds no line break
  // Every pass looks at the cancel flag and the timeout, whatever arrived:
  // a worker that writes without pause must not keep the study from either.
  for (;;) {
    const std::size_t newline = pending_.find('\n', searched);
    searched = pending_.size();
    if (newline != std::string::npos && newline <= kMaxAnswerBytes) {
      std::string reply = pending_.substr(0, newline);
      pending_.erase(0, newline + 1);
      if (!reply.empty() && reply.back() == '\r') reply.pop_back();
      forward_stderr();
      answer.output_tail = tail_;
      answer.ok = reply == "ok";
      if (!answer.ok) answer.failure = "the segmenter worker answered: " + reply;
      return answer;
    }
    if (pending_.size() > kMaxAnswerBytes) {
      stop(true);
      answer.failure = "the segmenter worker wrote more than " + std::to_string(kMaxAnswerBytes) +
                       " bytes on its stdout without a line break and was killed (an answer is "
                       "one line, 'ok' or why not; anything else belongs on stderr); the next "
                       "run starts it again";
      answer.output_tail = tail_;
      return answer;
    }
    if (progress.cancel != nullptr && progress.cancel->load()) {
      stop(true);
      throw Cancelled();
    }
    const double elapsed = seconds_since(start);
    if (timeout_seconds > 0.0 && elapsed > timeout_seconds) {
      stop(true);
      answer.failure = "the segmenter worker did not answer within " +
                       std::to_string(timeout_seconds) +
                       " s (segmenter_timeout) and was killed; the next run starts it again";
      answer.output_tail = tail_;
      return answer;
    }
    int wait_ms = kTickMilliseconds;
    if (timeout_seconds > 0.0) {
      wait_ms = std::min(wait_ms, static_cast<int>((timeout_seconds - elapsed) * 1000.0) + 1);
    }
    pollfd fds[2] = {{answers_fd_, POLLIN, 0}, {stderr_fd_, POLLIN, 0}};
    ::poll(fds, 2, wait_ms);
    forward_stderr();
    if (!read_answers()) return ended_without_answer();
    // Its shell gone while something it left holds its stdout: no answer
    // can come from the worker any more, only what is already written.
    if (pending_.find('\n', searched) == std::string::npos && has_exited()) {
      if (read_answers() && pending_.find('\n', searched) != std::string::npos) continue;
      return ended_without_answer();
    }
  }
}

std::shared_ptr<SegmenterWorker> idle_segmenter_worker() {
  return std::make_shared<SegmenterWorker>();
}

}  // namespace occlusion::job
