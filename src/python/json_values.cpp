#include "json_values.hpp"

#include <pybind11/numpy.h>

#include <limits>

#include "occlusion/app/errors.hpp"

namespace py = pybind11;

namespace occlusion::python {

py::object to_python(const Json::Value& value) {
  switch (value.type()) {
    case Json::nullValue:
      return py::none();
    case Json::booleanValue:
      return py::bool_(value.asBool());
    case Json::intValue:
      return py::int_(value.asInt64());
    case Json::uintValue:
      return py::int_(value.asUInt64());
    case Json::realValue:
      return py::float_(value.asDouble());
    case Json::stringValue:
      return py::str(value.asString());
    case Json::arrayValue: {
      py::list list;
      for (const Json::Value& item : value) list.append(to_python(item));
      return std::move(list);
    }
    case Json::objectValue: {
      py::dict dict;
      for (const std::string& name : value.getMemberNames()) {
        dict[py::str(name)] = to_python(value[name]);
      }
      return std::move(dict);
    }
  }
  return py::none();
}

Json::Value from_python(const py::handle& object, const std::string& key) {
  // bool before int: Python's bool is an int.
  if (py::isinstance<py::bool_>(object)) return Json::Value(object.cast<bool>());
  if (py::isinstance<py::int_>(object)) {
    // Python's int has no bound; a config value holds 64 bits.
    const py::int_ value = py::reinterpret_borrow<py::int_>(object);
    if (py::int_(0) <= value && value <= py::int_(std::numeric_limits<Json::UInt64>::max())) {
      return Json::Value(static_cast<Json::UInt64>(object.cast<unsigned long long>()));
    }
    if (py::int_(std::numeric_limits<Json::Int64>::min()) <= value && value < py::int_(0)) {
      return Json::Value(static_cast<Json::Int64>(object.cast<long long>()));
    }
    throw UsageError("'" + key + "': " + py::str(object).cast<std::string>() +
                     " does not fit in 64 bits");
  }
  if (py::isinstance<py::float_>(object)) return Json::Value(object.cast<double>());
  if (py::isinstance<py::str>(object)) return Json::Value(object.cast<std::string>());
  if (py::hasattr(object, "__fspath__"))
    return Json::Value(object.attr("__fspath__")().cast<std::string>());
  if (py::isinstance<py::array>(object)) return from_python(object.attr("tolist")(), key);
  if (py::hasattr(object, "dtype") && py::hasattr(object, "item")) {  // a numpy scalar
    return from_python(object.attr("item")(), key);
  }
  if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) {
    Json::Value list(Json::arrayValue);
    for (const py::handle item : object) list.append(from_python(item, key));
    return list;
  }
  if (py::isinstance<py::dict>(object)) {
    Json::Value dict(Json::objectValue);
    for (const auto& item : py::reinterpret_borrow<py::dict>(object)) {
      dict[py::str(item.first).cast<std::string>()] = from_python(item.second, key);
    }
    return dict;
  }
  throw UsageError("'" + key + "': a " +
                   py::str(py::type::of(object).attr("__name__")).cast<std::string>() +
                   " is no config value");
}

}  // namespace occlusion::python
