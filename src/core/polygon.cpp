#include "occlusion/core/polygon.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace occlusion {

namespace {

// Spread (standard deviation) ratio below which the points are taken to span
// only a line: well above float noise on collinear input, far below any real opening.
constexpr double kMinSpreadRatio = 1e-6;
constexpr double kBoundaryTolerance = 1e-9;
constexpr double kParallelTolerance = 1e-7;

double signed_area(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    twice += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
  }
  return 0.5 * twice;
}

}  // namespace

PlanarPolygon::PlanarPolygon(const std::vector<Eigen::Vector3d>& boundary) {
  if (boundary.size() < 3) {
    throw std::invalid_argument("polygon: needs at least 3 points, got " +
                                std::to_string(boundary.size()));
  }
  origin_ = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    if (!boundary[i].allFinite()) {
      throw std::invalid_argument("polygon: point " + std::to_string(i) + " is not finite");
    }
    origin_ += boundary[i];
  }
  origin_ /= static_cast<double>(boundary.size());

  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : boundary) {
    const Eigen::Vector3d centred = p - origin_;
    covariance += centred * centred.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  // Eigenvalues ascend: the least spread is across the plane, the most along it.
  const Eigen::Vector3d spread = solver.eigenvalues();
  if (solver.info() != Eigen::Success ||
      !(spread(1) > kMinSpreadRatio * kMinSpreadRatio * spread(2))) {
    throw std::invalid_argument(
        "polygon: the points are collinear or coincident, so span no plane");
  }
  normal_ = solver.eigenvectors().col(0).normalized();
  axis_u_ = solver.eigenvectors().col(2).normalized();
  axis_v_ = normal_.cross(axis_u_);

  vertices_2d_.reserve(boundary.size());
  for (const Eigen::Vector3d& p : boundary) vertices_2d_.push_back(to_plane(p));
  if (signed_area(vertices_2d_) < 0.0) {
    // The eigenvector's sign is arbitrary; fix it by the boundary's winding.
    normal_ = -normal_;
    axis_v_ = -axis_v_;
    for (Eigen::Vector2d& q : vertices_2d_) q.y() = -q.y();
  }
  Eigen::Vector2d lo = vertices_2d_.front(), hi = vertices_2d_.front();
  vertices_.reserve(boundary.size());
  for (const Eigen::Vector2d& q : vertices_2d_) {
    vertices_.push_back(origin_ + q.x() * axis_u_ + q.y() * axis_v_);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  boundary_tolerance_ = kBoundaryTolerance * (hi - lo).norm();
}

double PlanarPolygon::area() const {
  return std::abs(signed_area(vertices_2d_));
}

Eigen::Vector2d PlanarPolygon::to_plane(const Eigen::Vector3d& point) const {
  const Eigen::Vector3d offset = point - origin_;
  return {offset.dot(axis_u_), offset.dot(axis_v_)};
}

bool PlanarPolygon::on_boundary(const Eigen::Vector2d& point) const {
  const double tolerance_squared = boundary_tolerance_ * boundary_tolerance_;
  for (std::size_t i = 0, j = vertices_2d_.size() - 1; i < vertices_2d_.size(); j = i++) {
    const Eigen::Vector2d& a = vertices_2d_[j];
    const Eigen::Vector2d edge = vertices_2d_[i] - a;
    const double length_squared = edge.squaredNorm();
    double s = length_squared > 0.0 ? (point - a).dot(edge) / length_squared : 0.0;
    s = std::min(1.0, std::max(0.0, s));
    if ((point - (a + s * edge)).squaredNorm() <= tolerance_squared) return true;
  }
  return false;
}

bool PlanarPolygon::contains(const Eigen::Vector2d& point) const {
  if (on_boundary(point)) return true;
  // Crossing number: count edges crossed by the ray from `point` towards +u.
  // Each edge is half-open in v, so a crossing through a vertex counts once.
  bool inside = false;
  for (std::size_t i = 0, j = vertices_2d_.size() - 1; i < vertices_2d_.size(); j = i++) {
    const Eigen::Vector2d& a = vertices_2d_[j];
    const Eigen::Vector2d& b = vertices_2d_[i];
    if ((a.y() > point.y()) == (b.y() > point.y())) continue;
    const double u_cross = a.x() + (point.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    if (point.x() < u_cross) inside = !inside;
  }
  return inside;
}

std::optional<double> PlanarPolygon::intersect(const Ray& ray) const {
  const Eigen::Vector3d origin = ray.origin.cast<double>();
  const Eigen::Vector3d direction = ray.direction.cast<double>();
  const double denominator = normal_.dot(direction);
  if (!(std::abs(denominator) > kParallelTolerance * direction.norm())) return std::nullopt;
  const double t = normal_.dot(origin_ - origin) / denominator;
  if (!(t >= static_cast<double>(ray.t_min) && t <= static_cast<double>(ray.t_max))) {
    return std::nullopt;
  }
  if (!contains(to_plane(origin + t * direction))) return std::nullopt;
  return t;
}

}  // namespace occlusion
