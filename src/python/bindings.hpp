#pragma once
// The pieces of the `occlusion` Python module, one file each: module.cpp
// calls them in order (errors first, so the others can raise them).

#include <pybind11/pybind11.h>

namespace occlusion::python {

void bind_errors(pybind11::module_& m);
void bind_scenes(pybind11::module_& m);
void bind_io(pybind11::module_& m);
void bind_jobs(pybind11::module_& m);

}  // namespace occlusion::python
