#pragma once
// The pieces of the `occlusion` Python module, one file each: module.cpp
// calls them in order (errors first, so the others can raise them).

#include <pybind11/pybind11.h>

#include <vector>

#include "occlusion/core/point_cloud.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion::python {

void bind_errors(pybind11::module_& m);
void bind_scenes(pybind11::module_& m);
void bind_io(pybind11::module_& m);
void bind_jobs(pybind11::module_& m);

// A cloud as Python's occlusion.Cloud (bind_io registers the class), with
// `fields` as its extra per-point fields.
pybind11::object cloud_object(PointCloud cloud, std::vector<ScalarField> fields);

}  // namespace occlusion::python
