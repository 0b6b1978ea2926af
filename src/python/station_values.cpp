#include "station_values.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace py = pybind11;

namespace occlusion::python {

namespace {

py::dict frame_to_python(const SensorFrame& frame) {
  const Eigen::Vector3d& o = frame.origin;
  const Eigen::Quaterniond& q = frame.orientation;
  py::dict entry;
  entry["origin"] = py::make_tuple(o.x(), o.y(), o.z());
  entry["orientation"] = py::make_tuple(q.w(), q.x(), q.y(), q.z());
  entry["width"] = frame.width;
  entry["height"] = frame.height;
  return entry;
}

// ValueError naming `where` and what is expected, for a malformed entry.
SensorFrame frame_from_python(const py::handle& item, const std::string& where,
                              const char* expected) {
  if (!py::isinstance<py::dict>(item)) throw py::value_error(where + expected);
  try {
    const py::dict entry = py::reinterpret_borrow<py::dict>(item);
    SensorFrame frame;
    const auto origin = entry["origin"].cast<std::array<double, 3>>();
    frame.origin = Eigen::Vector3d(origin[0], origin[1], origin[2]);
    if (entry.contains("orientation")) {
      const auto q = entry["orientation"].cast<std::array<double, 4>>();
      frame.orientation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
    }
    if (entry.contains("width")) frame.width = entry["width"].cast<std::size_t>();
    if (entry.contains("height")) frame.height = entry["height"].cast<std::size_t>();
    if (!frame.origin.allFinite() || !(std::abs(frame.orientation.norm() - 1.0) <= 1e-3)) {
      throw py::value_error("needs a finite origin and a unit quaternion orientation");
    }
    frame.orientation.normalize();
    return frame;
  } catch (const py::error_already_set&) {
    throw py::value_error(where + expected);
  } catch (const py::cast_error&) {
    throw py::value_error(where + expected);
  } catch (const py::value_error& e) {
    throw py::value_error(where + ": " + e.what());
  }
}

}  // namespace

py::list stations_to_python(const std::vector<Station>& stations) {
  py::list out;
  for (const Station& station : stations) {
    py::dict entry = frame_to_python(station.frame);
    entry["name"] = station.name;
    out.append(entry);
  }
  return out;
}

std::vector<Station> stations_from_python(const py::handle& list, const std::string& name) {
  std::vector<Station> stations;
  std::size_t k = 0;
  for (const py::handle item : list) {
    const std::string where = name + "[" + std::to_string(k++) + "]";
    const char* expected =
        ": expected {'name': str, 'origin': (x, y, z), optional 'orientation': (w, x, y, z), "
        "'width', 'height'}";
    Station station;
    station.frame = frame_from_python(item, where, expected);
    try {
      station.name = py::reinterpret_borrow<py::dict>(item)["name"].cast<std::string>();
    } catch (const py::error_already_set&) {
      throw py::value_error(where + expected);
    } catch (const py::cast_error&) {
      throw py::value_error(where + expected);
    }
    stations.push_back(std::move(station));
  }
  return stations;
}

py::object sensor_to_python(const SensorFrame& sensor) {
  if (!sensor.single_view()) return py::none();
  return frame_to_python(sensor);
}

SensorFrame sensor_from_python(const py::handle& sensor, const std::string& name) {
  if (sensor.is_none()) return {};
  return frame_from_python(sensor, name,
                           ": expected None or {'origin': (x, y, z), optional 'orientation': "
                           "(w, x, y, z), 'width', 'height'}");
}

std::vector<std::uint32_t> pixels_from_array(const py::handle& object, const std::string& name) {
  const auto values = py::array_t<std::int64_t, py::array::forcecast>::ensure(object);
  if (!values || values.ndim() != 1) {
    throw py::value_error(name + ": expected a 1-D array of pixel indices");
  }
  std::vector<std::uint32_t> pixels(static_cast<std::size_t>(values.size()));
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const std::int64_t value = values.data()[i];
    if (value < 0 || value > std::numeric_limits<std::uint32_t>::max()) {
      throw py::value_error(name + "[" + std::to_string(i) + "] = " + std::to_string(value) +
                            " is no pixel index");
    }
    pixels[i] = static_cast<std::uint32_t>(value);
  }
  return pixels;
}

std::vector<float> float32_from_array(const py::handle& object, const std::string& name) {
  const auto values = py::array_t<float, py::array::forcecast>::ensure(object);
  if (!values || values.ndim() != 1)
    throw py::value_error(name + ": expected a 1-D array of numbers");
  return std::vector<float>(values.data(), values.data() + values.size());
}

}  // namespace occlusion::python
