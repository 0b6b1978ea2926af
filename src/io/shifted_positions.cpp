// ShiftedPositions::checked_shift (cloud_formats.hpp): the readers' refusal of
// finite points that float cannot hold.

#include <limits>
#include <sstream>

#include "cloud_formats.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::detail {

const Eigen::Vector3d& ShiftedPositions::checked_shift(const std::string& source) const {
  if (overflowed_ == 0) return shift_;
  std::ostringstream reason;
  reason.precision(9);
  reason << overflowed_ << " of " << points_ << " points have finite coordinates that float "
         << "cannot hold (beyond +-" << std::numeric_limits<float>::max() << ")";
  if (!shift_.isZero()) {
    reason << " once the global shift (" << shift_.x() << ", " << shift_.y() << ", " << shift_.z()
           << "), chosen from the first point, is subtracted";
  }
  reason << ", e.g. (" << first_overflow_.x() << ", " << first_overflow_.y() << ", "
         << first_overflow_.z() << "); the points are traced in float, so a cloud must fit in "
         << "float's range around its first point: fix the unit, or remove the far points";
  throw InputError(source, 0, reason.str());
}

}  // namespace occlusion::detail
