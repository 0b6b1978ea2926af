#pragma once
// Long C++ calls run with the GIL released and stay interruptible: Ctrl-C in
// Python only sets a flag that PyErr_CheckSignals() reads, so the C++ side
// takes the GIL briefly now and then to look at it.

#include <pybind11/pybind11.h>

#include <atomic>
#include <memory>
#include <mutex>

#include "occlusion/core/progress.hpp"

namespace occlusion::python {

// Call without the GIL: takes it, runs pending signal handlers, and throws
// pybind11::error_already_set (KeyboardInterrupt for Ctrl-C) if one raised.
void throw_if_interrupted();

// A Progress for a job: each report takes the GIL, calls `callback(stage,
// fraction)` when one is given, and checks for signals. A Python exception from
// either sets the job's cancel flag (the job then throws Cancelled at its next
// block) and is kept for `run` to raise in place of Cancelled.
class PythonProgress {
 public:
  explicit PythonProgress(pybind11::object callback);
  ~PythonProgress();

  // Runs `job(progress)` with the GIL released; re-raises the kept exception.
  template <class Job>
  auto run(Job&& job) -> decltype(job(std::declval<const Progress&>())) {
    try {
      pybind11::gil_scoped_release release;
      return job(progress_);
    } catch (const Cancelled&) {
      rethrow_kept();
      throw;
    }
  }

 private:
  void report(const std::string& stage, double fraction);
  void rethrow_kept();

  pybind11::object callback_;
  std::atomic<bool> cancel_{false};
  std::mutex mutex_;
  std::unique_ptr<pybind11::error_already_set> kept_;
  Progress progress_;
};

}  // namespace occlusion::python
