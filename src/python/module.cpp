// The extension module `occlusion._occlusion`, re-exported by the package
// `occlusion` (occlusion/__init__.py). A thin face over app/, analysis/ and
// io/: conversions between numpy and the library's types, nothing computed here.

#include "bindings.hpp"

PYBIND11_MODULE(_occlusion, m) {
  m.doc() =
      "Occlusion of indoor 3D scans: ray scenes over the octree, readers and writers for "
      "every format the tool reads.";
  occlusion::python::bind_errors(m);
  occlusion::python::bind_scenes(m);
  occlusion::python::bind_io(m);
  occlusion::python::bind_jobs(m);
}
