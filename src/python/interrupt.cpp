#include "interrupt.hpp"

namespace py = pybind11;

namespace occlusion::python {

void throw_if_interrupted() {
  py::gil_scoped_acquire hold;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

PythonProgress::PythonProgress(py::object callback) : callback_(std::move(callback)) {
  progress_.report = [this](const std::string& stage, double fraction) { report(stage, fraction); };
  progress_.cancel = &cancel_;
}

PythonProgress::~PythonProgress() {
  // The kept exception and the callback hold Python objects.
  py::gil_scoped_acquire hold;
  kept_.reset();
  callback_ = py::object();
}

void PythonProgress::report(const std::string& stage, double fraction) {
  // Analyses may report from several threads; one at a time, and nothing
  // more once an exception is kept.
  std::lock_guard<std::mutex> lock(mutex_);
  if (kept_) return;
  py::gil_scoped_acquire hold;
  try {
    if (callback_ && !callback_.is_none()) callback_(stage, fraction);
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  } catch (py::error_already_set& error) {
    kept_ = std::make_unique<py::error_already_set>(std::move(error));
    cancel_ = true;
  }
}

void PythonProgress::rethrow_kept() {
  if (!kept_) return;
  std::unique_ptr<py::error_already_set> kept = std::move(kept_);
  throw std::move(*kept);
}

}  // namespace occlusion::python
