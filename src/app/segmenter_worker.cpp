#include "segmenter_worker.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "shell_command.hpp"

namespace occlusion::job {

namespace {

constexpr double kExitGraceSeconds = 5.0;

std::string how_it_ended(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "ended";
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
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
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  while (::waitpid(pid_, &status, WNOHANG) == 0) {
    forward_stderr();
    const std::chrono::duration<double> waited = std::chrono::steady_clock::now() - start;
    if (waited.count() > kExitGraceSeconds) {
      ::kill(-pid_, SIGKILL);
      while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  forward_stderr();
  close_fd(requests_fd_);
  close_fd(stderr_fd_);
  pid_ = -1;
}

void SegmenterWorker::start(const std::string& command) {
  int requests[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, requests) != 0) {
    throw std::runtime_error(std::string("cannot make a socket pair: ") + std::strerror(errno));
  }
  int errors[2];
  if (::pipe2(errors, O_CLOEXEC) != 0) {
    ::close(requests[0]);
    ::close(requests[1]);
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    for (const int fd : {requests[0], requests[1], errors[0], errors[1]}) ::close(fd);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // Only async-signal-safe calls until exec: the parent may have threads.
    // dup2 clears close-on-exec on the copies.
    ::setpgid(0, 0);
    ::dup2(requests[1], STDIN_FILENO);
    ::dup2(requests[1], STDOUT_FILENO);
    ::dup2(errors[1], STDERR_FILENO);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  ::close(requests[1]);
  ::close(errors[1]);
  ::fcntl(errors[0], F_SETFL, ::fcntl(errors[0], F_GETFL) | O_NONBLOCK);
  pid_ = pid;
  requests_fd_ = requests[0];
  stderr_fd_ = errors[0];
  command_ = command;
  pending_.clear();
  tail_.clear();
  ++starts_;
}

void SegmenterWorker::forward_stderr() {
  if (stderr_fd_ >= 0) forward_output(stderr_fd_, tail_);
}

std::string SegmenterWorker::stop(bool kill) {
  if (pid_ < 0) return "not running";
  if (kill) ::kill(-pid_, SIGKILL);
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  forward_stderr();
  close_fd(requests_fd_);
  close_fd(stderr_fd_);
  pid_ = -1;
  return how_it_ended(status);
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
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const std::size_t newline = pending_.find('\n');
    if (newline != std::string::npos) {
      std::string reply = pending_.substr(0, newline);
      pending_.erase(0, newline + 1);
      if (!reply.empty() && reply.back() == '\r') reply.pop_back();
      forward_stderr();
      answer.output_tail = tail_;
      answer.ok = reply == "ok";
      if (!answer.ok) answer.failure = "the segmenter worker answered: " + reply;
      return answer;
    }
    pollfd fds[2] = {{requests_fd_, POLLIN, 0}, {stderr_fd_, POLLIN, 0}};
    ::poll(fds, 2, 20);
    forward_stderr();
    if (fds[0].revents != 0) {
      char buffer[4096];
      const ssize_t got = ::recv(requests_fd_, buffer, sizeof buffer, 0);
      if (got > 0) {
        pending_.append(buffer, static_cast<std::size_t>(got));
        continue;
      }
      if (got < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      // End of its stdout: it exited, or closed it, without answering.
      answer.failure = "the segmenter worker ended (" + stop(true) + ") without answering";
      answer.output_tail = tail_;
      return answer;
    }
    if (progress.cancel != nullptr && progress.cancel->load()) {
      stop(true);
      throw Cancelled();
    }
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (timeout_seconds > 0.0 && elapsed.count() > timeout_seconds) {
      stop(true);
      answer.failure = "the segmenter worker did not answer within " +
                       std::to_string(timeout_seconds) +
                       " s (segmenter_timeout) and was killed; the next run starts it again";
      answer.output_tail = tail_;
      return answer;
    }
  }
}

std::shared_ptr<SegmenterWorker> idle_segmenter_worker() {
  return std::make_shared<SegmenterWorker>();
}

}  // namespace occlusion::job
