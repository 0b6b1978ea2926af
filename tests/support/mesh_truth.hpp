#pragma once
// Clouds whose visibility is known exactly: a furnished room as a mesh, clouds
// sampled from it (at random, with density falling across the room, or as a
// laser scanner's gridded station scan), and the mesh itself traced as the
// truth. Header-only so that only the suites that use it compile it.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/sphere_directions.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/core/triangle_octree.hpp"
#include "support/scenes.hpp"

namespace occlusion::testing {

// A closed 6 x 5 x 3 m room, walls split into 1 m quads, with a table (top
// 4 cm thick on four legs), a tall cabinet, a freestanding 2 cm board, a low
// box, and a crate outside the room behind the wall x = 6 that no viewpoint
// inside can see. `window`: a 1.2 x 1 m hole in the wall x = 6 (from y 1.5 to
// 2.7, z 1 to 2), which the crate is not behind.
inline TriangleMesh furnished_room(bool window = false) {
  TriangleMesh mesh;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 5; ++j) {
      add_quad(mesh, Eigen::Vector3d(i, j, 0), x, y, "floor");
      add_quad(mesh, Eigen::Vector3d(i, j, 3), x, y, "ceiling");
    }
    for (int k = 0; k < 3; ++k) {
      add_quad(mesh, Eigen::Vector3d(i, 0, k), x, z, "wall");
      add_quad(mesh, Eigen::Vector3d(i, 5, k), x, z, "wall");
    }
  }
  for (int j = 0; j < 5; ++j) {
    for (int k = 0; k < 3; ++k) add_quad(mesh, Eigen::Vector3d(0, j, k), y, z, "wall");
  }
  if (window) {
    // The wall x = 6 around the hole [1.5, 2.7] x [1, 2].
    add_quad(mesh, Eigen::Vector3d(6, 0, 0), 1.5 * y, 3 * z, "wall");
    add_quad(mesh, Eigen::Vector3d(6, 2.7, 0), 2.3 * y, 3 * z, "wall");
    add_quad(mesh, Eigen::Vector3d(6, 1.5, 0), 1.2 * y, z, "wall");
    add_quad(mesh, Eigen::Vector3d(6, 1.5, 2), 1.2 * y, z, "wall");
  } else {
    for (int j = 0; j < 5; ++j) {
      for (int k = 0; k < 3; ++k) add_quad(mesh, Eigen::Vector3d(6, j, k), y, z, "wall");
    }
  }
  add_box(mesh, {1.5, 1.0, 0.72}, {3.1, 1.9, 0.76}, "table");
  for (const double lx : {1.55, 3.0}) {
    for (const double ly : {1.05, 1.8}) {
      add_box(mesh, {lx, ly, 0.0}, {lx + 0.05, ly + 0.05, 0.72}, "table");
    }
  }
  add_box(mesh, {4.6, 3.8, 0.0}, {5.6, 4.4, 1.9}, "bookcase");
  add_box(mesh, {3.6, 2.4, 0.0}, {4.6, 2.42, 1.5}, "board");
  add_box(mesh, {0.6, 3.2, 0.0}, {1.4, 4.0, 0.45}, "sofa");
  add_box(mesh, {7.0, 3.5, 0.0}, {7.6, 4.1, 0.6}, "clutter");  // outside, behind x = 6
  return mesh;
}

// A cloud sampled from a mesh, with each point's face.
struct SampledCloud {
  PointCloud cloud;
  std::vector<std::uint32_t> face;
};

// Random samples at `density` per m^2 where x = 0, thinning linearly to
// density / falloff at x = 7.6 (falloff 1: uniform).
inline SampledCloud sample_room(const TriangleMesh& mesh, double density, std::uint64_t seed,
                                double falloff = 1.0) {
  const MeshSamples samples = sample_mesh(mesh, density, seed);
  Rng rng(seed, 99);
  SampledCloud out;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double keep = 1.0 - (1.0 - 1.0 / falloff) * samples.points[i].x() / 7.6;
    if (rng.uniform() > keep) continue;
    out.cloud.positions.push_back(samples.points[i].cast<float>());
    out.face.push_back(samples.face[i]);
  }
  return out;
}

// Every quad of the mesh (faces 2k and 2k + 1, as add_quad makes them)
// sampled on a grid of `row_step` along its first edge and `column_step`
// along its second, each node moved by up to `jitter` along both: the
// anisotropic grid of a scanner's rows and columns, on every surface.
inline SampledCloud grid_sample_room(const TriangleMesh& mesh, double row_step, double column_step,
                                     double jitter, std::uint64_t seed) {
  Rng rng(seed, 98);
  SampledCloud out;
  for (std::size_t f = 0; f + 1 < mesh.face_count(); f += 2) {
    const Eigen::Vector3d corner = mesh.vertices[mesh.faces[f][0]];
    const Eigen::Vector3d a = mesh.vertices[mesh.faces[f][1]] - corner;
    const Eigen::Vector3d b = mesh.vertices[mesh.faces[f + 1][2]] - corner;
    const double du = row_step / a.norm(), dv = column_step / b.norm();
    for (double u = 0.5 * du; u < 1.0; u += du) {
      for (double v = 0.5 * dv; v < 1.0; v += dv) {
        const double ju = std::clamp(u + jitter / a.norm() * (rng.uniform() - 0.5), 0.0, 1.0);
        const double jv = std::clamp(v + jitter / b.norm() * (rng.uniform() - 0.5), 0.0, 1.0);
        out.cloud.positions.push_back((corner + ju * a + jv * b).cast<float>());
        // add_quad's first triangle holds u >= v, its second v >= u.
        out.face.push_back(static_cast<std::uint32_t>(ju >= jv ? f : f + 1));
      }
    }
  }
  return out;
}

// What a terrestrial laser scanner at `station` records: the first surface on
// each ray of a grid of azimuth steps `azimuth_step` and elevation steps
// `elevation_step` (radians; elevations from -85 to +85 degrees), over the
// azimuths [0, azimuth_span) (less than 2 pi: a partial scan).
inline SampledCloud station_scan(const TriangleMesh& mesh, const Eigen::Vector3d& station,
                                 double azimuth_step, double elevation_step,
                                 double azimuth_span = 2.0 * M_PI) {
  const TriangleOctree tree(pack_triangles(mesh.triangles()));
  SampledCloud out;
  const double limit = 85.0 * M_PI / 180.0;
  for (double azimuth = 0.0; azimuth < azimuth_span; azimuth += azimuth_step) {
    for (double elevation = -limit; elevation <= limit; elevation += elevation_step) {
      const Eigen::Vector3d d(std::cos(elevation) * std::cos(azimuth),
                              std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
      const auto hit = tree.intersect(Ray{station.cast<float>(), d.cast<float>()});
      if (!hit) continue;
      out.cloud.positions.push_back((station + hit->t_hit * d).cast<float>());
      out.face.push_back(hit->primitive_id);
    }
  }
  return out;
}

// The truth: whether the segment from `viewpoint` to each point meets no face
// but the point's own (1e-5 x the room's size spared at both ends).
inline std::vector<std::uint8_t> mesh_visibility(const TriangleMesh& mesh, const SampledCloud& s,
                                                 const Eigen::Vector3d& viewpoint) {
  const TriangleOctree tree(pack_triangles(mesh.triangles()));
  const double margin = 1e-4;
  std::vector<std::uint8_t> visible(s.cloud.size());
  for (std::size_t i = 0; i < s.cloud.size(); ++i) {
    const Eigen::Vector3d d = s.cloud.positions[i].cast<double>() - viewpoint;
    const double length = d.norm();
    const Ray ray{viewpoint.cast<float>(), d.cast<float>(), static_cast<float>(margin / length),
                  static_cast<float>(1.0 - margin / length)};
    visible[i] = tree.occluded(ray, s.face[i]) ? 0 : 1;
  }
  return visible;
}

// The truth for -poc: the share of a viewpoint's light-source rays (as
// compute_cloud_occlusion casts them) that meet no face.
inline double mesh_escape_share(const TriangleMesh& mesh, const Eigen::Vector3d& viewpoint,
                                std::size_t viewpoint_index, std::size_t rays, std::uint64_t seed) {
  const TriangleOctree tree(pack_triangles(mesh.triangles()));
  const SphereDirections directions(DirectionSampling::kUniform, rays, seed, viewpoint_index);
  std::size_t escapes = 0;
  for (std::size_t k = 0; k < rays; ++k) {
    escapes += tree.occluded(Ray{viewpoint.cast<float>(), directions(k).cast<float>()}) ? 0 : 1;
  }
  return static_cast<double>(escapes) / static_cast<double>(rays);
}

}  // namespace occlusion::testing
