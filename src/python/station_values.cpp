#include "station_values.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>

namespace py = pybind11;

namespace occlusion::python {

py::list stations_to_python(const std::vector<Station>& stations) {
  py::list out;
  for (const Station& station : stations) {
    const Eigen::Vector3d& o = station.frame.origin;
    const Eigen::Quaterniond& q = station.frame.orientation;
    py::dict entry;
    entry["name"] = station.name;
    entry["origin"] = py::make_tuple(o.x(), o.y(), o.z());
    entry["orientation"] = py::make_tuple(q.w(), q.x(), q.y(), q.z());
    entry["width"] = station.frame.width;
    entry["height"] = station.frame.height;
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
    if (!py::isinstance<py::dict>(item)) throw py::value_error(where + expected);
    try {
      const py::dict entry = py::reinterpret_borrow<py::dict>(item);
      Station station;
      station.name = entry["name"].cast<std::string>();
      const auto origin = entry["origin"].cast<std::array<double, 3>>();
      station.frame.origin = Eigen::Vector3d(origin[0], origin[1], origin[2]);
      if (entry.contains("orientation")) {
        const auto q = entry["orientation"].cast<std::array<double, 4>>();
        station.frame.orientation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
      }
      if (entry.contains("width")) station.frame.width = entry["width"].cast<std::size_t>();
      if (entry.contains("height")) station.frame.height = entry["height"].cast<std::size_t>();
      if (!station.frame.origin.allFinite() ||
          !(std::abs(station.frame.orientation.norm() - 1.0) <= 1e-3)) {
        throw py::value_error("needs a finite origin and a unit quaternion orientation");
      }
      station.frame.orientation.normalize();
      stations.push_back(std::move(station));
    } catch (const py::error_already_set&) {
      throw py::value_error(where + expected);
    } catch (const py::cast_error&) {
      throw py::value_error(where + expected);
    } catch (const py::value_error& e) {
      throw py::value_error(where + ": " + e.what());
    }
  }
  return stations;
}

std::vector<float> float32_from_array(const py::handle& object, const std::string& name) {
  const auto values = py::array_t<float, py::array::forcecast>::ensure(object);
  if (!values || values.ndim() != 1)
    throw py::value_error(name + ": expected a 1-D array of numbers");
  return std::vector<float>(values.data(), values.data() + values.size());
}

}  // namespace occlusion::python
