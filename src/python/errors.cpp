// One classification of the library's exceptions into Python's, the same one
// the CLI's exit codes and the server's error codes follow
// (docs/architecture.md, "Error policy"):
//   UsageError   -> occlusion.UsageError(ValueError), the message names the key
//   InputError   -> occlusion.InputError(OSError, ValueError) with path, line,
//                   reason; FileNotFoundError when the file does not exist
//   OutputError  -> occlusion.OutputError(OSError) with path, reason
//   Cancelled    -> KeyboardInterrupt (a job stopped by Ctrl-C re-raises the
//                   interrupt itself; see interrupt.hpp)
//   std::invalid_argument -> occlusion.UsageError (a ValueError), as the CLI's exit 2
//   std::bad_alloc -> MemoryError

#include <pybind11/pybind11.h>

#include <cerrno>
#include <filesystem>
#include <string>

#include "bindings.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/io/input_error.hpp"

namespace py = pybind11;

namespace occlusion::python {
namespace {

// Owned by the module for the life of the interpreter: never released, as
// pybind11 does with its own exception types.
PyObject* usage_error_type = nullptr;
PyObject* input_error_type = nullptr;
PyObject* output_error_type = nullptr;

// A new exception class `occlusion.<name>` with these bases. Its str() is the
// message alone: OSError's own str() would prefix "[Errno None]".
PyObject* make_exception_type(py::module_& m, const char* name, py::tuple bases, const char* doc) {
  py::dict body;
  body["__module__"] = "occlusion";
  body["__doc__"] = doc;
  body["__str__"] = py::module_::import("builtins").attr("BaseException").attr("__str__");
  py::object type = py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(&PyType_Type))(
      name, bases, body);
  m.attr(name) = type;
  return type.release().ptr();
}

void raise(PyObject* type, py::object instance) {
  PyErr_SetObject(type, instance.ptr());
}

void raise_input_error(const InputError& error) {
  if (error.line == 0 && !error.path.empty() && !std::filesystem::exists(error.path)) {
    py::object instance = py::reinterpret_borrow<py::object>(PyExc_FileNotFoundError)(
        ENOENT, error.reason, error.path);
    raise(PyExc_FileNotFoundError, instance);
    return;
  }
  py::object instance = py::reinterpret_borrow<py::object>(input_error_type)(error.what());
  instance.attr("filename") = error.path;
  instance.attr("path") = error.path;
  instance.attr("line") = error.line;
  instance.attr("reason") = error.reason;
  raise(input_error_type, instance);
}

void raise_output_error(const OutputError& error) {
  py::object instance = py::reinterpret_borrow<py::object>(output_error_type)(error.what());
  instance.attr("filename") = error.path;
  instance.attr("path") = error.path;
  instance.attr("reason") = error.reason;
  raise(output_error_type, instance);
}

}  // namespace

void bind_errors(py::module_& m) {
  usage_error_type = make_exception_type(
      m, "UsageError", py::make_tuple(py::handle(PyExc_ValueError)),
      "A bad argument: unknown key, wrong type or value out of range. The message names it.");
  input_error_type = make_exception_type(
      m, "InputError", py::make_tuple(py::handle(PyExc_OSError), py::handle(PyExc_ValueError)),
      "A file that cannot be read or does not say what it should. Attributes: path "
      "(also filename), line (1-based, 0 for the whole file) and reason.");
  output_error_type =
      make_exception_type(m, "OutputError", py::make_tuple(py::handle(PyExc_OSError)),
                          "An output that could not be written. Attributes: path (also "
                          "filename) and reason.");

  // The app layer's one classification (app/errors.hpp) picks the Python type.
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const std::exception& error) {
      switch (classify(error)) {
        case ErrorKind::kUsage:
          raise(usage_error_type,
                py::reinterpret_borrow<py::object>(usage_error_type)(error.what()));
          return;
        case ErrorKind::kInput:
          raise_input_error(dynamic_cast<const InputError&>(error));
          return;
        case ErrorKind::kOutput:
          raise_output_error(dynamic_cast<const OutputError&>(error));
          return;
        case ErrorKind::kCancelled:
          PyErr_SetString(PyExc_KeyboardInterrupt, error.what());
          return;
        case ErrorKind::kResource:
          PyErr_SetString(PyExc_MemoryError, error.what());
          return;
        case ErrorKind::kInternal:
          break;
      }
      throw;  // pybind11's own translation (RuntimeError and the standard ones)
    }
  });
}

}  // namespace occlusion::python
