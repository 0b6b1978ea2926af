#pragma once
// The app layer's one classification of errors. Every face maps it its own
// way: the CLI to exit codes, the server to protocol codes, Python to
// exceptions (classify() below is the single place that sorts them).

#include <exception>
#include <stdexcept>
#include <string>

namespace occlusion {

// A bad command line or configuration (unknown key, wrong type, bad value).
// The CLI maps it to exit code 2, the server to an "invalid_request" reply.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A usage error about one declared key. `what()` names the key as `spelling`
// (the config name unless a face knows better); faces that know how the user
// wrote the key re-spell it with respelled().
struct KeyError : UsageError {
  KeyError(std::string key_name, std::string problem_text, const std::string& spelling)
      : UsageError(spelling + " " + problem_text),
        key(std::move(key_name)),
        problem(std::move(problem_text)) {}
  KeyError(const std::string& key_name, std::string problem_text)
      : KeyError(key_name, std::move(problem_text), key_name) {}
  std::string key;      // config name, e.g. "point_radius"
  std::string problem;  // e.g. "must be a number > 0"
};

enum class ErrorKind {
  kUsage,      // bad options, keys or values: exit 2
  kInput,      // an input file that cannot be read or is malformed: exit 3
  kOutput,     // an output that cannot be written: exit 1
  kCancelled,  // the caller asked to stop: exit 1
  kResource,   // out of memory, or over a declared budget: exit 1
  kInternal,   // anything else (a bug): exit 1
};

// Sorts any exception the jobs throw (UsageError, io's InputError and
// OutputError, Cancelled, std::bad_alloc, ...).
ErrorKind classify(const std::exception& error);
// "usage_error", "input_error", ...: the name faces print and Python exposes.
const char* error_kind_name(ErrorKind kind);

}  // namespace occlusion
