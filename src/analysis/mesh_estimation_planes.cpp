// One cluster to one polygon (thesis 4.1.2): RANSAC plane, inliers projected
// onto it, 2-D convex hull, area-weighted centroid, fan.
//
// PCL quirks this file works around rather than trusts:
// - ConvexHull in 2-D picks a projection (xy, yz or xz) from the normal of the
//   first, middle and last input points; if those three are (nearly)
//   collinear (the diagonal of a wall scanned row by row) the projection can
//   flatten the polygon to a line and qhull fails (QH6013, QH6154). Points on
//   a line give QH6154 too, or, after float rounding, a
//   sliver "hull" of noise. So the hull gets the points in the plane's own
//   coordinates (z = 0) with a wide triangle in those three slots, and lines
//   are caught before PCL sees them.
// - On failure PCL prints to stderr and returns an empty result; every result
//   is checked here and becomes a reason.

#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_plane.h>
#include <pcl/surface/convex_hull.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "mesh_estimation_stages.hpp"
#include "occlusion/core/polygon_fan.hpp"

namespace occlusion::mesh_estimation {

namespace {

// RANSAC's stopping confidence: stop once a better plane is this unlikely.
constexpr double kRansacConfidence = 0.99;
// Hull corners closer than this times the polygon's extent are one corner.
constexpr double kSameCorner = 1e-9;

// Eigenvalues (ascending) of the points' covariance.
template <int N, class Points, class Get>
Eigen::Matrix<double, N, 1> spread(const Points& points, Get get) {
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;
  Vector mean = Vector::Zero();
  for (const auto& p : points) mean += get(p);
  mean /= static_cast<double>(points.size());
  Matrix covariance = Matrix::Zero();
  for (const auto& p : points) {
    const Vector centred = get(p) - mean;
    covariance += centred * centred.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Matrix>(covariance, Eigen::EigenvaluesOnly).eigenvalues();
}

// True when the second-largest spread is negligible next to the largest.
template <int N>
bool is_line(const Eigen::Matrix<double, N, 1>& eigenvalues) {
  const double largest = eigenvalues(N - 1);
  return !(eigenvalues(N - 2) > kMinSpreadRatio * kMinSpreadRatio * largest);
}

Eigen::Vector3d any_perpendicular(const Eigen::Vector3d& normal) {
  Eigen::Index least = 0;
  normal.cwiseAbs().minCoeff(&least);
  return normal.cross(Eigen::Vector3d::Unit(least)).normalized();
}

// The indices of a wide triangle among the points: the extremes along u and
// the point farthest from the line through them.
std::array<std::size_t, 3> wide_triangle(const std::vector<Eigen::Vector2f>& points) {
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (points[i].x() < points[lo].x()) lo = i;
    if (points[i].x() > points[hi].x()) hi = i;
  }
  const Eigen::Vector2f edge = points[hi] - points[lo];
  std::size_t far = 0;
  float best = -1.0f;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == lo || i == hi) continue;
    const Eigen::Vector2f offset = points[i] - points[lo];
    const float distance = std::abs(edge.x() * offset.y() - edge.y() * offset.x());
    if (distance > best) {
      best = distance;
      far = i;
    }
  }
  return {lo, far, hi};
}

// The hull's corners without float-rounding twins, which would make triangles
// of no area that read_obj would skip (and -moc warn about) in the written mesh.
std::vector<Eigen::Vector2d> distinct_corners(const Cloud& corners) {
  std::vector<Eigen::Vector2d> polygon;
  polygon.reserve(corners.size());
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const auto& p : corners) {
    polygon.emplace_back(p.x, p.y);
    lo = lo.cwiseMin(polygon.back());
    hi = hi.cwiseMax(polygon.back());
  }
  const double tolerance = kSameCorner * (hi - lo).norm();
  std::vector<Eigen::Vector2d> distinct;
  for (const Eigen::Vector2d& q : polygon) {
    if (distinct.empty() || (q - distinct.back()).norm() > tolerance) distinct.push_back(q);
  }
  while (distinct.size() > 1 && (distinct.front() - distinct.back()).norm() <= tolerance) {
    distinct.pop_back();
  }
  return distinct;
}

std::string count_text(std::size_t count, const char* what) {
  return std::to_string(count) + " " + what;
}

}  // namespace

PlaneOutcome fit_plane(const Cloud::ConstPtr& cloud, const pcl::PointIndices& cluster,
                       const RegionGrowingOptions& options) {
  PlaneOutcome outcome;
  const std::size_t points = cluster.indices.size();
  if (points < 3) {
    outcome.reason = SkipReason::kTooFewPoints;
    outcome.detail = count_text(points, "points; a plane needs 3");
    return outcome;
  }
  const auto position = [&cloud](pcl::index_t i) {
    return (*cloud)[static_cast<std::size_t>(i)].getVector3fMap().cast<double>().eval();
  };
  if (is_line<3>(spread<3>(cluster.indices, position))) {
    outcome.reason = SkipReason::kCollinear;
    outcome.detail = count_text(points, "points on a line");
    return outcome;
  }

  // What PCL's SACSegmentation (plane, RANSAC, optimised coefficients) and
  // ProjectInliers do for a plane, call for call, with the same model and
  // method: their switches over every model type took minutes to compile.
  const auto model = pcl::make_shared<pcl::SampleConsensusModelPlane<pcl::PointXYZ>>(
      cloud, cluster.indices, /*random=*/false);
  pcl::RandomSampleConsensus<pcl::PointXYZ> ransac(model, options.ransac_distance);
  ransac.setProbability(kRansacConfidence);
  ransac.setMaxIterations(static_cast<int>(options.ransac_iterations));
  pcl::Indices inliers;
  Eigen::VectorXf coefficients;
  if (ransac.computeModel(0)) {
    ransac.getInliers(inliers);
    Eigen::VectorXf found;
    ransac.getModelCoefficients(found);
    model->optimizeModelCoefficients(inliers, found, coefficients);
    model->selectWithinDistance(coefficients, options.ransac_distance, inliers);
  }
  outcome.inliers = inliers.size();
  const bool has_plane =
      coefficients.size() == 4 && coefficients.allFinite() && coefficients.head<3>().norm() > 0.0f;
  if (outcome.inliers < 3 || !has_plane) {
    outcome.reason = SkipReason::kNoPlane;
    outcome.detail = "RANSAC found no plane with 3 or more of " + count_text(points, "points") +
                     " within ransac_distance";
    return outcome;
  }

  Cloud projected;
  model->projectPoints(inliers, coefficients, projected, /*copy_data_fields=*/false);

  ClusterPlane plane;
  const Eigen::Vector3d raw_normal(coefficients[0], coefficients[1], coefficients[2]);
  plane.normal = raw_normal.normalized();
  plane.offset = coefficients[3] / raw_normal.norm();
  plane.axis_u = any_perpendicular(plane.normal);
  plane.axis_v = plane.normal.cross(plane.axis_u);
  plane.origin.setZero();
  for (const auto& p : projected) plane.origin += p.getVector3fMap().cast<double>();
  plane.origin /= static_cast<double>(projected.size());
  plane.inliers_2d.reserve(projected.size());
  for (const auto& p : projected) {
    const Eigen::Vector3d offset = p.getVector3fMap().cast<double>() - plane.origin;
    plane.inliers_2d.emplace_back(static_cast<float>(offset.dot(plane.axis_u)),
                                  static_cast<float>(offset.dot(plane.axis_v)));
  }
  const auto planar = [](const Eigen::Vector2f& p) { return p.cast<double>().eval(); };
  if (projected.size() < 3 || is_line<2>(spread<2>(plane.inliers_2d, planar))) {
    outcome.reason = SkipReason::kCollinear;
    outcome.detail = "the plane's " + count_text(projected.size(), "inliers lie on a line");
    return outcome;
  }
  outcome.plane = std::move(plane);
  return outcome;
}

PolygonOutcome build_polygon(const ClusterPlane& plane) {
  PolygonOutcome outcome;
  const std::vector<Eigen::Vector2f>& points = plane.inliers_2d;
  const std::size_t count = points.size();
  // PCL reads the plane off the points in slots 0, count / 2 and count - 1.
  const std::array<std::size_t, 3> triangle = wide_triangle(points);
  const std::array<std::size_t, 3> slots = {0, count / 2, count - 1};
  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = i;
  for (int k = 0; k < 3; ++k) {
    const auto at = std::find(order.begin(), order.end(), triangle[k]);
    std::iter_swap(order.begin() + static_cast<std::ptrdiff_t>(slots[k]), at);
  }
  Cloud::Ptr flat(new Cloud);
  flat->reserve(count);
  for (const std::size_t i : order)
    flat->push_back(pcl::PointXYZ(points[i].x(), points[i].y(), 0.0f));

  pcl::ConvexHull<pcl::PointXYZ> hull;
  hull.setDimension(2);
  hull.setInputCloud(flat);
  Cloud corners;
  std::vector<pcl::Vertices> polygons;
  hull.reconstruct(corners, polygons);

  std::vector<Eigen::Vector2d> polygon = distinct_corners(corners);
  const double area = polygon_signed_area(polygon);
  if (polygon.size() < 3 || !(std::abs(area) > 0.0)) {
    outcome.reason = SkipReason::kHullFailed;
    outcome.detail = "qhull built no polygon from " + count_text(count, "projected inliers");
    return outcome;
  }
  if (area < 0.0) std::reverse(polygon.begin(), polygon.end());

  ClusterPolygon result;
  const auto to_3d = [&plane](const Eigen::Vector2d& q) {
    return (plane.origin + q.x() * plane.axis_u + q.y() * plane.axis_v).eval();
  };
  result.vertices.reserve(polygon.size());
  for (const Eigen::Vector2d& q : polygon) result.vertices.push_back(to_3d(q));
  result.centroid = to_3d(polygon_centroid_2d(polygon));
  result.area = std::abs(area);
  outcome.polygon = std::move(result);
  return outcome;
}

}  // namespace occlusion::mesh_estimation
