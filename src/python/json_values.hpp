#pragma once
// JSON values to Python objects and back: a job's report becomes the dict the
// CLI would print with --json, and keyword arguments become the job's config
// section, checked by the app layer's own config checker.

#include <json/value.h>
#include <pybind11/pybind11.h>

#include <string>

namespace occlusion::python {

// null -> None, bool, int, float, str, list, dict.
pybind11::object to_python(const Json::Value& value);

// bool, int, float, str, os.PathLike (as its path), numpy scalars and arrays,
// lists, tuples and dicts of those. UsageError naming `key` for anything else.
Json::Value from_python(const pybind11::handle& object, const std::string& key);

}  // namespace occlusion::python
