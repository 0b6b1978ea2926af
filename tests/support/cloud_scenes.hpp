#pragma once
// Point clouds whose occlusion is known exactly, built in code. Header-only so
// that only the suites that use it compile it.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion::testing {

// Keeps a grid node, given its integer coordinates along the rectangle's edges:
// lets a test cut holes exactly on grid lines, without rounding.
using KeepNode = std::function<bool(int i, int j)>;

// Grid nodes corner + i * step * a + j * step * b for i in [0, na], j in [0, nb],
// a and b unit, both edge ends included. Labels are set when the cloud has them.
inline void add_grid(PointCloud& cloud, const Eigen::Vector3d& corner, const Eigen::Vector3d& a,
                     const Eigen::Vector3d& b, int na, int nb, double step, std::int32_t label = -1,
                     const KeepNode& keep = nullptr) {
  for (int i = 0; i <= na; ++i) {
    for (int j = 0; j <= nb; ++j) {
      if (keep && !keep(i, j)) continue;
      cloud.positions.push_back((corner + i * step * a + j * step * b).cast<float>());
      if (label >= 0) cloud.labels.push_back(label);
    }
  }
}

// The six faces of the box [0, n_x step] x [0, n_y step] x [0, n_z step] as
// grid nodes (edge nodes appear on both faces that share them, which is harmless).
// `keep_wall_x_max(j, k)` may cut a hole into the face x = max, indexed by (y, z).
inline void add_box_grid(PointCloud& cloud, int nx, int ny, int nz, double step,
                         std::int32_t label = -1, const KeepNode& keep_wall_x_max = nullptr) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  add_grid(cloud, Eigen::Vector3d::Zero(), x, y, nx, ny, step, label);         // floor
  add_grid(cloud, nz * step * z, x, y, nx, ny, step, label);                   // ceiling
  add_grid(cloud, Eigen::Vector3d::Zero(), y, z, ny, nz, step, label);         // x = 0
  add_grid(cloud, nx * step * x, y, z, ny, nz, step, label, keep_wall_x_max);  // x = max
  add_grid(cloud, Eigen::Vector3d::Zero(), x, z, nx, nz, step, label);         // y = 0
  add_grid(cloud, ny * step * y, x, z, nx, nz, step, label);                   // y = max
}

// `count` points on the sphere |p - centre| = radius, spread evenly (a golden
// spiral), skipping those for which skip(unit direction) is true.
inline void add_sphere_shell(PointCloud& cloud, const Eigen::Vector3d& centre, double radius,
                             std::size_t count,
                             const std::function<bool(const Eigen::Vector3d&)>& skip = nullptr) {
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(count);
    const double ring = std::sqrt(1.0 - z * z);
    const double angle = static_cast<double>(i) * golden_angle;
    const Eigen::Vector3d d(ring * std::cos(angle), ring * std::sin(angle), z);
    if (skip && skip(d)) continue;
    cloud.positions.push_back((centre + radius * d).cast<float>());
  }
}

// Points on the circle of directions at polar angle `polar` from +z, on the
// sphere of `radius` around `centre`, `spacing` apart along the circle.
inline void add_circle(PointCloud& cloud, const Eigen::Vector3d& centre, double radius,
                       double polar, double spacing) {
  const double ring = radius * std::sin(polar);
  const auto count = static_cast<int>(std::ceil(2.0 * M_PI * ring / spacing));
  for (int k = 0; k < count; ++k) {
    const double angle = 2.0 * M_PI * k / count;
    const Eigen::Vector3d p(ring * std::cos(angle), ring * std::sin(angle),
                            radius * std::cos(polar));
    cloud.positions.push_back((centre + p).cast<float>());
  }
}

// Solid angle of the rectangle [u1, u2] x [v1, v2] lying in a plane at distance
// `distance` from the eye, in plane coordinates centred on the eye's foot point.
inline double rectangle_solid_angle(double distance, double u1, double u2, double v1, double v2) {
  const auto corner = [distance](double u, double v) {
    return std::atan2(u * v, distance * std::sqrt(distance * distance + u * u + v * v));
  };
  return corner(u2, v2) - corner(u1, v2) - corner(u2, v1) + corner(u1, v1);
}

// A plate before a wall, seen by two stations. The wall x = 0 (y in
// [-1.6, 1.6], z in [0, 2]) sampled every 2 cm at cell centres, a plate
// x = 1, y and z in [-0.2, 0.2] around (1, 0, 1), and the stations A
// (2, -1, 1) and B (2, 1, 1). The wall is twice as far from a station as the
// plate, so the plate's shadow is the plate doubled about the station's foot:
// from A, y in [0.6, 1.4], from B, y in [-1.4, -0.6], z in [0.6, 1.4] for
// both. A 5 x 5 patch at x = 0.9 just behind the plate's middle is hidden
// from both. Labels: 0 wall, 1 plate, 2 the patch.
struct PlateBeforeWall {
  static constexpr double kStep = 0.02;
  enum Part : std::int32_t { kWall, kPlate, kBehind };
  static constexpr std::size_t kBehindPoints = 25;
  static Eigen::Vector3d a() { return {2, -1, 1}; }
  static Eigen::Vector3d b() { return {2, 1, 1}; }

  static PointCloud cloud() {
    PointCloud c;
    const Eigen::Vector3d y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
    add_grid(c, {0, -1.6 + kStep / 2, kStep / 2}, y, z, 159, 99, kStep, kWall);
    add_grid(c, {1, -0.2, 0.8}, y, z, 20, 20, kStep, kPlate);
    add_grid(c, {0.9, -0.04, 0.96}, y, z, 4, 4, kStep, kBehind);
    return c;
  }

  // What A and B see of a point of `part`, seen from A then B: how many see
  // it and the first (1 for A, 2 for B, -1 none); count -1 for a wall point
  // within `band` of a shadow's edge, which the model of the points decides.
  struct Seen {
    int count = -1;
    int first = -1;
  };
  static Seen expected(const Eigen::Vector3f& p, std::int32_t part, double band) {
    if (part == kBehind) return {0, -1};
    if (part == kPlate) return {2, 1};
    const auto inside = [&](double centre_y, double margin) {
      return std::abs(p.y() - centre_y) < 0.4 + margin && std::abs(p.z() - 1.0) < 0.4 + margin;
    };
    if (inside(1.0, -band)) return {1, 2};   // A's shadow: B alone
    if (inside(-1.0, -band)) return {1, 1};  // B's shadow: A alone
    if (!inside(1.0, band) && !inside(-1.0, band)) return {2, 1};
    return {};
  }
};

}  // namespace occlusion::testing
