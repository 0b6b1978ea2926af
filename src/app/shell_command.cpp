#include "shell_command.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace occlusion::job {

namespace {

void kill_group(pid_t pid, int& status) {
  ::kill(-pid, SIGKILL);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace

void forward_output(int fd, std::string& tail) {
  char buffer[65536];
  // A bounded share per call: a child that writes without pause must not keep
  // the caller from its timeout and cancel checks.
  for (std::size_t forwarded = 0; forwarded < kForwardedPerCall; forwarded += sizeof buffer) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got <= 0) return;  // empty (EAGAIN), closed, or an error: nothing more now
    const std::size_t size = static_cast<std::size_t>(got);
    std::size_t written = 0;
    while (written < size) {
      const ssize_t w = ::write(STDERR_FILENO, buffer + written, size - written);
      if (w <= 0) break;
      written += static_cast<std::size_t>(w);
    }
    tail.append(buffer, size);
    if (tail.size() > kShellOutputTail) tail.erase(0, tail.size() - kShellOutputTail);
  }
}

ShellResult run_shell_command(const std::string& command, const Progress& progress,
                              double timeout_seconds) {
  progress.check_cancel();
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) {
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // Only async-signal-safe calls until exec: the parent may have threads.
    ::setpgid(0, 0);
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, STDIN_FILENO);
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::dup2(pipe_fds[1], STDERR_FILENO);
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Set it here too: whichever of the two runs first, the group exists before a kill.
  ::setpgid(pid, pid);
  ::close(pipe_fds[1]);
  const int output = pipe_fds[0];
  ::fcntl(output, F_SETFL, ::fcntl(output, F_GETFL) | O_NONBLOCK);
  ShellResult result;
  int status = 0;
  for (;;) {
    forward_output(output, result.output_tail);
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      ::close(output);
      throw std::runtime_error(std::string("cannot wait for the command: ") + std::strerror(errno));
    }
    if (progress.cancel != nullptr && progress.cancel->load()) {
      kill_group(pid, status);
      ::close(output);
      throw Cancelled();
    }
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (timeout_seconds > 0.0 && elapsed.count() > timeout_seconds) {
      kill_group(pid, status);
      result.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // What the shell wrote just before it ended; a child it left behind that
  // still holds the pipe does not hold us up (non-blocking).
  forward_output(output, result.output_tail);
  ::close(output);
  if (WIFEXITED(status)) {
    result.status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.status = 128 + WTERMSIG(status);
  } else {
    result.status = 1;
  }
  return result;
}

}  // namespace occlusion::job
