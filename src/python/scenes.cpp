// Low-level ray scenes for people who trace their own rays, in the shape
// Open3D's RaycastingScene has: TriangleScene (a mesh), DiscScene (a point
// cloud as the jobs trace it by default, one disc per point) and SphereScene
// (a point cloud, one sphere of `radius` per point), each over the library's
// octree, with batch `intersect` and `occluded`. Ray rules are the library's
// (docs/architecture.md, "Ray rules"): closed [t_min, t_max], directions need
// not be unit (t is in units of the direction), ties go to the lower id.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "interrupt.hpp"
#include "json_values.hpp"
#include "numpy_views.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/sphere_octree.hpp"
#include "occlusion/core/surfel_octree.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace py = pybind11;

namespace occlusion::python {
namespace {

// Rays are traced in blocks of this many; between blocks the GIL is taken
// briefly to look for Ctrl-C, so an interrupt lands within one block.
constexpr std::size_t kInterruptBlock = std::size_t{1} << 16;
// Rays handed to one thread at a time within a block (as Octree's batch calls).
constexpr std::size_t kGrain = 256;

// The rays of a batch call, read straight from the caller's arrays.
struct RayArguments {
  Vec3View origins;
  Vec3View directions;
  ScalarView t_min;
  ScalarView t_max;
  std::size_t count = 0;

  RayArguments(const py::handle& o, const py::handle& d, const py::handle& lo, const py::handle& hi)
      : origins(o, "origins", true),
        directions(d, "directions"),
        t_min(lo, "t_min"),
        t_max(hi, "t_max"),
        count(directions.size()) {
    if (!origins.broadcast() && origins.size() != count) {
      throw py::value_error("origins: " + std::to_string(origins.size()) + " rows for " +
                            std::to_string(count) + " directions");
    }
    t_min.expect_rows(count);
    t_max.expect_rows(count);
  }

  Ray ray(std::size_t i) const {
    Ray ray;
    ray.origin = origins[i];
    ray.direction = directions[i];
    ray.t_min = t_min[i];
    ray.t_max = t_max[i];
    return ray;
  }
};

// body(i) for every ray, on `threads` threads, without the GIL, interruptible.
template <class Body>
void for_each_ray(std::size_t count, unsigned threads, const Body& body) {
  py::gil_scoped_release release;
  for (std::size_t begin = 0; begin < count; begin += kInterruptBlock) {
    const std::size_t block = std::min(kInterruptBlock, count - begin);
    // A batch of one grain runs on this thread: starting workers would cost
    // more than it (27 us against 5 us for one ray).
    const unsigned used = block <= kGrain ? 1u : threads;
    parallel_for(block, kGrain, used, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = begin + b; i < begin + e; ++i) body(i);
    });
    throw_if_interrupted();
  }
}

template <class Shape>
py::tuple intersect(const Octree<Shape>& octree, const py::handle& origins,
                    const py::handle& directions, const py::handle& t_min, const py::handle& t_max,
                    unsigned threads) {
  const RayArguments rays(origins, directions, t_min, t_max);
  py::array_t<float> t_hit(static_cast<py::ssize_t>(rays.count));
  py::array_t<std::uint32_t> ids(static_cast<py::ssize_t>(rays.count));
  float* t_out = t_hit.mutable_data();
  std::uint32_t* id_out = ids.mutable_data();
  for_each_ray(rays.count, threads, [&](std::size_t i) {
    const std::optional<Hit> hit = octree.intersect(rays.ray(i));
    t_out[i] = hit ? hit->t_hit : std::numeric_limits<float>::infinity();
    id_out[i] = hit ? hit->primitive_id : kNoPrimitive;
  });
  return py::make_tuple(t_hit, ids);
}

template <class Shape>
py::array_t<bool> occluded(const Octree<Shape>& octree, const py::handle& origins,
                           const py::handle& directions, const py::handle& t_min,
                           const py::handle& t_max, unsigned threads) {
  const RayArguments rays(origins, directions, t_min, t_max);
  py::array_t<bool> out(static_cast<py::ssize_t>(rays.count));
  bool* flags = out.mutable_data();
  for_each_ray(rays.count, threads,
               [&](std::size_t i) { flags[i] = octree.occluded(rays.ray(i)); });
  return out;
}

OctreeOptions octree_options(OctreeOptions options, double octree_resolution,
                             bool enable_acceleration) {
  if (!(octree_resolution >= 0.0)) throw py::value_error("octree_resolution: must be >= 0");
  options.min_cell_size = static_cast<float>(octree_resolution);
  options.enable_acceleration = enable_acceleration;
  return options;
}

TriangleOctree build_triangle_scene(const py::handle& vertices, const py::handle& faces,
                                    double octree_resolution, bool enable_acceleration) {
  const TriangleMesh mesh = mesh_from_arrays(vertices, faces, py::none(), py::none());
  const OctreeOptions options = octree_options({}, octree_resolution, enable_acceleration);
  py::gil_scoped_release release;
  return TriangleOctree(pack_triangles(mesh.triangles()), options);
}

SphereOctree build_sphere_scene(const py::handle& points, double radius, double octree_resolution,
                                bool enable_acceleration) {
  std::vector<Eigen::Vector3f> centres = points_from_array(points, "points");
  const OctreeOptions options =
      octree_options(sphere_octree_options(), octree_resolution, enable_acceleration);
  LargeVector<Sphere> spheres = make_spheres(centres, static_cast<float>(radius));
  py::gil_scoped_release release;
  return SphereOctree(std::move(spheres), options);
}

SurfelOctree build_disc_scene(const py::handle& points, const py::handle& normals,
                              const py::handle& radii, double disc_coverage,
                              unsigned normal_neighbours, double octree_resolution,
                              bool enable_acceleration) {
  if (normals.is_none() != radii.is_none()) {
    throw py::value_error(
        "normals and radii: give both, or neither (then they are estimated as the jobs do)");
  }
  const OctreeOptions options =
      octree_options(surfel_octree_options(), octree_resolution, enable_acceleration);
  PointCloud cloud;
  cloud.positions = points_from_array(points, "points");
  if (normals.is_none()) {
    SurfelOptions estimate;
    estimate.coverage = disc_coverage;
    estimate.neighbours = normal_neighbours;
    estimate.keep_thickness = false;  // a scene traces discs only
    py::gil_scoped_release release;
    return SurfelOctree(estimate_surfels(cloud, estimate).surfels, options);
  }
  const std::vector<Eigen::Vector3f> normal_rows = points_from_array(normals, "normals");
  const ScalarView radius_rows(radii, "radii");
  radius_rows.expect_rows(cloud.size());
  std::vector<float> radius_values(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) radius_values[i] = radius_rows[i];
  LargeVector<Surfel> surfels = make_surfels(cloud.positions, normal_rows, radius_values);
  py::gil_scoped_release release;
  return SurfelOctree(std::move(surfels), options);
}

constexpr const char* kIntersectDoc = R"doc(Closest hit of each ray.

origins: (N, 3) or (3,) for one origin shared by all rays; directions: (N, 3).
float32 or float64 arrays are read in place (other numeric dtypes converted).
Directions need not be unit: t is in units of the direction. A hit counts iff
t_min <= t <= t_max; t_min and t_max are numbers or (N,) arrays.
threads: 0 = all cores. Ctrl-C interrupts (KeyboardInterrupt).
Returns (t, primitive_id): float32 (N,) with inf where nothing is hit, and
uint32 (N,) with NO_PRIMITIVE (2**32 - 1) there. Equal t: the lower id.)doc";

constexpr const char* kOccludedDoc = R"doc(Whether each ray hits anything in [t_min, t_max].

Arguments as for intersect. Returns bool (N,). Stops at the first hit, so it is
faster than intersect: a shadow ray from p to q is origins=p, directions=q - p,
t_max=1.)doc";

template <class Scene>
void bind_queries(py::class_<Scene>& scene) {
  const auto inf = std::numeric_limits<double>::infinity();
  scene
      .def(
          "intersect",
          [](const Scene& self, py::handle origins, py::handle directions, py::handle t_min,
             py::handle t_max, unsigned threads) {
            return intersect(self, origins, directions, t_min, t_max, threads);
          },
          py::arg("origins"), py::arg("directions"), py::arg("t_min") = 0.0, py::arg("t_max") = inf,
          py::kw_only(), py::arg("threads") = 0u, kIntersectDoc)
      .def(
          "occluded",
          [](const Scene& self, py::handle origins, py::handle directions, py::handle t_min,
             py::handle t_max, unsigned threads) {
            return occluded(self, origins, directions, t_min, t_max, threads);
          },
          py::arg("origins"), py::arg("directions"), py::arg("t_min") = 0.0, py::arg("t_max") = inf,
          py::kw_only(), py::arg("threads") = 0u, kOccludedDoc)
      .def("__len__", &Scene::size)
      .def_property_readonly(
          "bounds",
          [](const Scene& self) {
            const Aabb& box = self.bounds();
            return py::make_tuple(
                to_numpy<float>(std::vector<float>{box.lo.x(), box.lo.y(), box.lo.z()}),
                to_numpy<float>(std::vector<float>{box.hi.x(), box.hi.y(), box.hi.z()}));
          },
          "(lo, hi): float32 (3,) corners of the box around every primitive.")
      .def_property_readonly(
          "stats", [](const Scene& self) { return to_python(to_json(self.stats())); },
          "The octree's figures as the jobs' reports give them: inner_nodes, leaves, depth, "
          "largest_leaf, memory_bytes.");
}

}  // namespace

void bind_scenes(py::module_& m) {
  m.attr("NO_PRIMITIVE") = kNoPrimitive;

  py::class_<TriangleOctree> triangles(m, "TriangleScene", R"doc(A triangle mesh for ray queries.

TriangleScene(vertices, faces, *, octree_resolution=0.0, enable_acceleration=True)
vertices: (V, 3) float; faces: (M, 3) integer vertex indices. Primitive ids are
face indices. Edges belong to the triangle, both sides are hit, rays in a
triangle's plane and degenerate triangles miss. octree_resolution is the
smallest octree cell edge (0 = no limit); enable_acceleration=False makes every
query a brute-force loop. ValueError for an index out of range or a vertex that
is not finite.)doc");
  triangles.def(py::init(&build_triangle_scene), py::arg("vertices"), py::arg("faces"),
                py::kw_only(), py::arg("octree_resolution") = 0.0,
                py::arg("enable_acceleration") = true);
  bind_queries(triangles);

  py::class_<SphereOctree> spheres(m, "SphereScene", R"doc(A point cloud for ray queries.

SphereScene(points, radius, *, octree_resolution=0.0, enable_acceleration=True)
Each point is a sphere of `radius` (the jobs' point_radius); primitive ids are
point indices. The hit is the sphere's entry, or its exit for a ray that starts
inside it; tangent rays hit. ValueError for a radius that is not finite and
positive, or a point that is not finite.)doc");
  spheres.def(py::init(&build_sphere_scene), py::arg("points"), py::arg("radius"), py::kw_only(),
              py::arg("octree_resolution") = 0.0, py::arg("enable_acceleration") = true);
  bind_queries(spheres);

  py::class_<SurfelOctree> discs(m, "DiscScene",
                                 R"doc(A point cloud for ray queries, as the jobs trace it.

DiscScene(points, normals=None, radii=None, *, disc_coverage=0.99,
          normal_neighbours=16, octree_resolution=0.0, enable_acceleration=True)
Each point is a disc (a surfel): centred on the point, in the plane of `normals`
(a zero row: a sphere of that radius), of `radii` (a number or (N,) array).
Without normals and radii they are estimated as the jobs' primitive disc does:
a plane fitted to each point's normal_neighbours nearest, a radius from their
density that closes disc_coverage of the surface (README, Point model).
Primitive ids are point indices. A disc is two-sided and closed; a ray in its
plane misses it. ValueError for sizes that differ, a radius that is not finite
and positive, or a point or normal that is not finite.)doc");
  discs.def(py::init(&build_disc_scene), py::arg("points"), py::arg("normals") = py::none(),
            py::arg("radii") = py::none(), py::kw_only(),
            py::arg("disc_coverage") = kDefaultDiscCoverage,
            py::arg("normal_neighbours") = kDefaultNormalNeighbours,
            py::arg("octree_resolution") = 0.0, py::arg("enable_acceleration") = true);
  discs.def_property_readonly(
      "normals",
      [](const SurfelOctree& self) {
        std::vector<float> values;
        values.reserve(3 * self.size());
        for (PrimitiveId id = 0; id < self.size(); ++id) {
          const Eigen::Vector3f& n = self.shape(id).normal;
          values.insert(values.end(), {n.x(), n.y(), n.z()});
        }
        py::array_t<float> out = to_numpy<float>(std::move(values));
        return out.reshape({static_cast<py::ssize_t>(self.size()), py::ssize_t{3}});
      },
      "float32 (N, 3): each point's unit normal, zero where it is a sphere.");
  discs.def_property_readonly(
      "radii",
      [](const SurfelOctree& self) {
        std::vector<float> values(self.size());
        for (PrimitiveId id = 0; id < self.size(); ++id) values[id] = self.shape(id).radius;
        return to_numpy<float>(std::move(values));
      },
      "float32 (N,): each point's radius.");
  bind_queries(discs);
}

}  // namespace occlusion::python
