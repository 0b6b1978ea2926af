#pragma once
// A scan's pose: the rigid motion that takes its points from the scanner's
// own frame into the scene's (scan frame -> scene frame), in metres, in the
// tool's frame (right-handed, z up unless the scene says otherwise). Read and
// written in the formats registration tools and data sets use
// (docs/formats.md, "Poses"):
//   matrix  a 4 x 4 matrix in rows, 16 numbers (CloudCompare's and Cyclone's
//           registration matrix .txt, numpy.savetxt of a 4 x 4, Open3D);
//           translation in metres; the last row must be 0 0 0 1
//   tum     `tx ty tz qx qy qz qw`, or a TUM trajectory line with a leading
//           timestamp (8 numbers); translation in metres, the quaternion's
//           w last
//   3dtk    3DTK's scanNNN.pose: a line `tx ty tz` in centimetres, then a
//           line of Euler angles `ax ay az` in degrees, in 3DTK's frame
//           (left-handed, x right, y up, z forward); the rotation is
//           Rx(ax) Ry(ay) Rz(az) applied to column vectors (p' = R p + t),
//           as 3DTK's EulerToMatrix4 builds it. Converted to the tool's
//           frame as 3DTK's own xyz reader converts (x, y, z) metres
//           right-handed to (-100 y, 100 z, 100 x): see point_from_3dtk.
// A rotation block may be off a rotation by kPoseRotationTolerance (a file
// written with 4 decimals); it is then taken as the rotation nearest to it.
// Anything further off (a scale, a shear, a mirror) is refused, never
// orthonormalised into some other pose.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace occlusion {

enum class PoseFormat { kMatrix, kTum, k3dtk };

// The names a project file or a command line gives a format: "matrix", "tum",
// "3dtk", and all of them for messages ("matrix, tum, 3dtk").
std::string_view pose_format_name(PoseFormat format);
std::optional<PoseFormat> pose_format_from_name(std::string_view name);
std::string pose_format_names();

// How far a rotation block may be from a rotation: the largest entry of
// R^T R - I (matrix), or | |q| - 1 | (TUM).
inline constexpr double kPoseRotationTolerance = 1e-3;

struct ScanPose {
  Eigen::Isometry3d scan_to_scene = Eigen::Isometry3d::Identity();  // metres, tool's frame
  PoseFormat format = PoseFormat::kMatrix;  // the format it was read in, and is written in
  // A TUM trajectory line's timestamp, kept so that the pose is written back
  // as the line it was read from.
  std::optional<double> timestamp;
};

// The pose `numbers` give in `format`, in the format's order (16 for a
// matrix, 7 or 8 for TUM, 6 for 3DTK: translation, then angles).
// std::invalid_argument saying why for a wrong count, a number that is not
// finite, a last row other than 0 0 0 1 or a rotation block that is no
// rotation (see above).
ScanPose pose_from_numbers(const std::vector<double>& numbers, PoseFormat format);
// The numbers pose_from_numbers reads back as `pose` (within double rounding),
// in pose.format.
std::vector<double> pose_numbers(const ScanPose& pose);

// The format of the pose file `path` holding `text`, where it can be told:
// a `.pose` file is 3DTK's; otherwise 16 numbers are a matrix and one line
// of 8 a TUM trajectory line. InputError naming the file with what to say
// instead where it cannot: 7 numbers (TUM's qx qy qz qw or a w-first
// quaternion?), 6 (3DTK's centimetres and degrees, or metres and radians?),
// several TUM lines (which one?), any other count.
PoseFormat detect_pose_format(const std::string& path, std::string_view text);

// The pose in the file `path`, in `format` or else as detect_pose_format
// tells. `#` lines are comments (TUM's header). InputError naming the file,
// and the line where there is one, for anything pose_from_numbers refuses,
// a token that is not a number, or a TUM file of several lines. The numbers
// may be laid out in lines as the user likes (3DTK reads its six so); a
// matrix's are read in rows.
ScanPose read_pose_file(const std::string& path, std::optional<PoseFormat> format = {});
// The text read_pose_file reads back as `pose` (numbers in the fewest digits
// that read back exactly), in pose.format.
std::string pose_file_text(const ScanPose& pose);
// Written atomically (atomic_file.hpp); OutputError if it cannot be.
void write_pose_file(const std::string& path, const ScanPose& pose);

// 3DTK's frame: a point of a .3d file (centimetres; x right, y up, z
// forward, left-handed) in the tool's frame (metres; x forward, y left, z
// up): (z, -x, y) / 100.
Eigen::Vector3d point_from_3dtk(const Eigen::Vector3d& point_cm);

}  // namespace occlusion
