#pragma once
// A cloud's stations and per-point values as Python sees them (Cloud.stations,
// Cloud.intensities, Cloud.station_ids, and the same names as arguments).

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion::python {

// [{"name", "origin": (x, y, z) relative to the cloud's shift, as positions,
//   "orientation": (w, x, y, z), "width", "height"}, ...]
pybind11::list stations_to_python(const std::vector<Station>& stations);
// The same list back; ValueError naming `name` and the entry at fault.
std::vector<Station> stations_from_python(const pybind11::handle& list, const std::string& name);
// (N,) numbers as float32; ValueError naming `name` otherwise.
std::vector<float> float32_from_array(const pybind11::handle& object, const std::string& name);

}  // namespace occlusion::python
