#pragma once
// Points handed to PCL (internal to analysis/). PCL works in float and its
// kd-tree (FLANN) squares coordinate differences: a cloud 5e6 units from the
// origin keeps half a unit of precision, and points near ±3e38 overflow to inf
// and abort the process. So points go to PCL in a local frame around the
// centre of their bounds, and only when every local coordinate is in a range
// whose squared distances float still holds.

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace occlusion::pcl_frame {

// Beyond this a squared distance (3 × (2 × 1e15)²) still fits a float with
// room to spare; no scan comes near it.
constexpr double kMaxLocalCoordinate = 1e15;

// The centre of the finite points' bounds (zero when none is finite).
inline Eigen::Vector3d centre_of(const std::vector<Eigen::Vector3f>& points) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-INFINITY);
  for (const auto& p : points) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p.cast<double>());
    hi = hi.cwiseMax(p.cast<double>());
  }
  if (!(lo.array() <= hi.array()).all()) return Eigen::Vector3d::Zero();
  return 0.5 * (lo + hi);
}

// p - centre as float, or std::invalid_argument naming `analysis` when a
// coordinate is out of PCL's range.
inline Eigen::Vector3f to_local(const Eigen::Vector3f& p, const Eigen::Vector3d& centre,
                                const std::string& analysis) {
  const Eigen::Vector3d local = p.cast<double>() - centre;
  if (!(local.cwiseAbs().maxCoeff() <= kMaxLocalCoordinate)) {
    throw std::invalid_argument(
        analysis +
        ": a point is not finite or lies more than 1e15 units from the points' "
        "centre, beyond what PCL's float kd-tree can search; remove the stray far "
        "points (or fix the unit) first");
  }
  return local.cast<float>();
}

}  // namespace occlusion::pcl_frame
