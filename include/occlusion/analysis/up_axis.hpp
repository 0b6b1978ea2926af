#pragma once
// Which way is up: a signed coordinate axis ("+z", the default; "-y" for
// camera-frame data such as Kinect frames, where +y points down). Everything
// that means "height" (the baseline segmenter's floor and ceiling, the num_vp
// grid's mid-height and floor plan) reads it from here.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace occlusion {

struct UpAxis {
  int axis = 2;  // 0 = x, 1 = y, 2 = z
  int sign = 1;  // +1 or -1

  // "+z", "z", "-y", ... (case-insensitive); std::invalid_argument otherwise.
  static UpAxis parse(const std::string& text);
  std::string name() const;  // "+z"
  Eigen::Vector3d vector() const;
  double height(const Eigen::Vector3f& p) const { return sign * static_cast<double>(p[axis]); }
};

// Does the data agree with `up`? Indoor scenes are dominated by their floor
// (and ceiling), so the thinnest slab holding the most points is normally
// perpendicular to up. Per axis, the points are binned into slabs of
// 1/kUpSlabs of the extent on that axis; when the fullest slab of another
// axis holds more than kUpDisagreement x the fullest slab across `up`, the
// largest flat structure is not horizontal and a message says which axis it
// is perpendicular to. The margin is small because a room's floor is only a
// little larger than its largest wall (4 x 3 m against 4 x 2.5 m); a long
// corridor, whose walls outgrow its floor, is flagged though right, which the
// message allows for. Scenes not aligned to their axes have no dominant slab
// and are never flagged. Only the axis is checked: the sign cannot be seen
// from the planes.
inline constexpr int kUpSlabs = 200;
inline constexpr double kUpDisagreement = 1.1;
std::optional<std::string> check_up_axis(const std::vector<Eigen::Vector3f>& points,
                                         const UpAxis& up);

}  // namespace occlusion
