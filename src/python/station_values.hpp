#pragma once
// A cloud's stations, sensor and per-point values as Python sees them
// (Cloud.stations, Cloud.sensor, Cloud.intensities, Cloud.station_ids,
// Cloud.pixels, and the same names as arguments).

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion::python {

// [{"name", "origin": (x, y, z) relative to the cloud's shift, as positions,
//   "orientation": (w, x, y, z), "width", "height"}, ...]
pybind11::list stations_to_python(const std::vector<Station>& stations);
// The same list back; ValueError naming `name` and the entry at fault.
std::vector<Station> stations_from_python(const pybind11::handle& list, const std::string& name);
// A single-view frame's sensor: {"origin", "orientation", "width", "height"}
// as a station's entry, or None for a cloud that is none (and back).
pybind11::object sensor_to_python(const SensorFrame& sensor);
SensorFrame sensor_from_python(const pybind11::handle& sensor, const std::string& name);
// (N,) pixel indices (PointCloud::pixels); ValueError naming `name` for
// another shape or a value outside [0, 2^32).
std::vector<std::uint32_t> pixels_from_array(const pybind11::handle& object,
                                             const std::string& name);
// (N,) numbers as float32; ValueError naming `name` otherwise.
std::vector<float> float32_from_array(const pybind11::handle& object, const std::string& name);

}  // namespace occlusion::python
