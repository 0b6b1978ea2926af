#include "occlusion/analysis/up_axis.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace occlusion {

namespace {

const char kAxisNames[3] = {'x', 'y', 'z'};

// Share of the points in the fullest of kUpSlabs slabs across `axis`.
double fullest_slab(const std::vector<Eigen::Vector3f>& points, int axis) {
  float lo = points.front()[axis], hi = lo;
  for (const auto& p : points) {
    lo = std::min(lo, p[axis]);
    hi = std::max(hi, p[axis]);
  }
  if (!(hi > lo)) return 1.0;  // all points in one plane across this axis
  std::vector<std::size_t> counts(kUpSlabs, 0);
  const double scale = kUpSlabs / (static_cast<double>(hi) - lo);
  for (const auto& p : points) {
    const auto slab = static_cast<int>((static_cast<double>(p[axis]) - lo) * scale);
    ++counts[static_cast<std::size_t>(std::clamp(slab, 0, kUpSlabs - 1))];
  }
  return static_cast<double>(*std::max_element(counts.begin(), counts.end())) /
         static_cast<double>(points.size());
}

}  // namespace

UpAxis UpAxis::parse(const std::string& text) {
  std::string s;
  for (const char c : text) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  UpAxis up;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    up.sign = s[0] == '-' ? -1 : 1;
    s.erase(0, 1);
  }
  if (s.size() != 1 || s[0] < 'x' || s[0] > 'z') {
    throw std::invalid_argument("up must be a signed axis (+x, -x, +y, -y, +z, -z), got '" + text +
                                "'");
  }
  up.axis = s[0] - 'x';
  return up;
}

std::string UpAxis::name() const {
  return std::string(sign < 0 ? "-" : "+") + kAxisNames[axis];
}

Eigen::Vector3d UpAxis::vector() const {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  v[axis] = sign;
  return v;
}

std::optional<std::string> check_up_axis(const std::vector<Eigen::Vector3f>& points,
                                         const UpAxis& up) {
  if (points.size() < 2) return std::nullopt;
  double share[3];
  for (int axis = 0; axis < 3; ++axis) share[axis] = fullest_slab(points, axis);
  int strongest = up.axis;
  for (int axis = 0; axis < 3; ++axis) {
    if (share[axis] > share[strongest]) strongest = axis;
  }
  if (share[strongest] <= kUpDisagreement * share[up.axis]) return std::nullopt;
  std::ostringstream message;
  message.precision(3);
  message << "up is " << up.name() << ", but the largest flat structure is perpendicular to "
          << kAxisNames[strongest] << " (" << 100.0 * share[strongest]
          << " % of the points lie in one thin slab across " << kAxisNames[strongest] << ", only "
          << 100.0 * share[up.axis] << " % across " << kAxisNames[up.axis]
          << "): is the floor perpendicular to " << kAxisNames[strongest]
          << "? Camera-frame data (Kinect: +y down) needs up -y";
  return message.str();
}

}  // namespace occlusion
