#include "occlusion/analysis/baseline_segmenter.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace occlusion {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A plane's polygon, measured: it spans the plane's cluster and the edge
// points the plane recovered, which its cluster's points alone fall short of
// by the width of the edge strips region growing leaves out.
struct PolygonShape {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kInfinity);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-kInfinity);
  // Along the plane's horizontal direction (walls: their width).
  Eigen::Vector3d along = Eigen::Vector3d::Zero();
  double along_lo = kInfinity, along_hi = -kInfinity;

  void add(const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    along_lo = std::min(along_lo, along.dot(p));
    along_hi = std::max(along_hi, along.dot(p));
  }
  bool empty() const { return along_lo > along_hi; }
};

void check(const BaselineOptions& o) {
  const bool fine = o.max_tilt_degrees >= 0.0 && o.max_tilt_degrees <= 45.0 &&
                    o.height_band >= 0.0 && o.min_wall_height >= 0.0 && o.min_wall_width >= 0.0 &&
                    o.snap_distance >= 0.0;
  if (!fine) throw std::invalid_argument("segment_baseline: an option is out of range");
}

BaselineClass classify(const EstimatedPlane& plane, const PolygonShape& shape,
                       const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       const BaselineOptions& o) {
  const int up = o.up.axis;
  const double tilt = o.max_tilt_degrees * M_PI / 180.0;
  const double vertical_component = std::abs(plane.normal[up]);
  // Heights along the signed up axis: the floor is at the low end.
  const double bottom = o.up.sign > 0 ? lo[up] : -hi[up];
  const double top = o.up.sign > 0 ? hi[up] : -lo[up];
  const double height = top - bottom;
  if (shape.empty()) return BaselineClass::kClutter;
  if (vertical_component >= std::cos(tilt)) {
    const double h = o.up.sign * plane.centroid[up];
    if (h <= bottom + o.height_band * height) return BaselineClass::kFloor;
    if (h >= top - o.height_band * height) return BaselineClass::kCeiling;
    return BaselineClass::kClutter;
  }
  if (vertical_component <= std::sin(tilt)) {
    const int a = (up + 1) % 3, b = (up + 2) % 3;
    const double short_side = std::min(hi[a] - lo[a], hi[b] - lo[b]);
    const bool tall = shape.hi[up] - shape.lo[up] >= o.min_wall_height * height;
    const bool wide = shape.along_hi - shape.along_lo >= o.min_wall_width * short_side;
    if (tall && wide) return BaselineClass::kWall;
  }
  return BaselineClass::kClutter;
}

std::int32_t id_of(BaselineClass c, const BaselineOptions& o) {
  switch (c) {
    case BaselineClass::kFloor:
      return o.floor_id;
    case BaselineClass::kCeiling:
      return o.ceiling_id;
    case BaselineClass::kWall:
      return o.wall_id;
    case BaselineClass::kClutter:
      break;
  }
  return o.clutter_id;
}

}  // namespace

BaselineSegmentation segment_baseline(const PointCloud& cloud, const MeshEstimate& estimate,
                                      const BaselineOptions& options) {
  check(options);
  const std::vector<std::int32_t>& cluster = estimate.point_cluster;
  if (!cluster.empty() && cluster.size() != cloud.size()) {
    throw std::invalid_argument("segment_baseline: " + std::to_string(cluster.size()) +
                                " cluster ids for " + std::to_string(cloud.size()) + " points");
  }
  BaselineSegmentation result;
  if (const auto disagreement = check_up_axis(cloud.positions, options.up)) {
    result.warnings.push_back(*disagreement);
  }
  result.labels.assign(cloud.size(), options.clutter_id);
  result.points[static_cast<std::size_t>(BaselineClass::kClutter)] = cloud.size();
  if (cloud.size() == 0 || cluster.empty() || estimate.planes.empty()) {
    result.plane_classes.assign(estimate.planes.size(), BaselineClass::kClutter);
    return result;
  }

  // Cluster id -> plane index (skipped clusters have none); mesh group = cluster id.
  std::size_t largest_id = 0;
  for (const auto& plane : estimate.planes) largest_id = std::max(largest_id, plane.cluster);
  constexpr std::size_t kNoPlane = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> plane_of(largest_id + 1, kNoPlane);
  std::vector<PolygonShape> shapes(estimate.planes.size());
  for (std::size_t k = 0; k < estimate.planes.size(); ++k) {
    plane_of[estimate.planes[k].cluster] = k;
    const Eigen::Vector3d across = options.up.vector().cross(estimate.planes[k].normal);
    if (across.norm() > 1e-9) shapes[k].along = across.normalized();
  }
  const TriangleMesh& mesh = estimate.mesh;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::size_t group = mesh.face_group[f];
    const std::size_t k = group <= largest_id ? plane_of[group] : kNoPlane;
    if (k == kNoPlane) continue;
    for (const auto vertex : mesh.faces[f]) shapes[k].add(mesh.vertices[vertex]);
  }
  const auto plane_index = [&](std::size_t i) {
    const std::int32_t id = cluster[i];
    return id >= 0 && static_cast<std::size_t>(id) <= largest_id
               ? plane_of[static_cast<std::size_t>(id)]
               : kNoPlane;
  };

  Eigen::Vector3f lo_f, hi_f;
  cloud.bounds(lo_f, hi_f);
  const Eigen::Vector3d lo = lo_f.cast<double>(), hi = hi_f.cast<double>();
  std::vector<std::size_t> structural;
  for (std::size_t k = 0; k < estimate.planes.size(); ++k) {
    result.plane_classes.push_back(classify(estimate.planes[k], shapes[k], lo, hi, options));
    if (result.plane_classes[k] != BaselineClass::kClutter) structural.push_back(k);
  }

  result.points = {};
  const double snap = options.snap_distance;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    BaselineClass c = BaselineClass::kClutter;
    const std::size_t own = plane_index(i);
    if (own != kNoPlane) {
      c = result.plane_classes[own];
    } else {
      const Eigen::Vector3d p = cloud.positions[i].cast<double>();
      double nearest = kInfinity;
      for (const std::size_t k : structural) {
        const EstimatedPlane& plane = estimate.planes[k];
        const double distance = std::abs(plane.normal.dot(p) + plane.offset);
        const bool inside = (p.array() >= shapes[k].lo.array() - snap).all() &&
                            (p.array() <= shapes[k].hi.array() + snap).all();
        if (distance <= snap && inside && distance < nearest) {
          nearest = distance;
          c = result.plane_classes[k];
        }
      }
    }
    result.labels[i] = id_of(c, options);
    ++result.points[static_cast<std::size_t>(c)];
  }
  return result;
}

}  // namespace occlusion
