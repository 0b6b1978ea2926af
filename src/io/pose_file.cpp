#include "occlusion/io/pose_file.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "file_names.hpp"
#include "number_text.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCentimetresPerMetre = 100.0;

// The tool's axes in 3DTK's: tool = kFrom3dtk * 3dtk (x = z, y = -x, z = y).
// Its determinant is -1: the two frames differ in handedness, and a rotation
// conjugated by it (kFrom3dtk R kFrom3dtk^T) is a rotation again.
Eigen::Matrix3d from_3dtk_axes() {
  Eigen::Matrix3d axes;
  axes << 0, 0, 1, -1, 0, 0, 0, 1, 0;
  return axes;
}

std::string number_text(double value) {
  std::string text;
  detail::append_number(text, value);
  return text;
}

void check_finite(const std::vector<double>& numbers) {
  for (const double value : numbers) {
    if (!std::isfinite(value)) {
      throw std::invalid_argument("the pose holds a value that is not finite (" +
                                  number_text(value) + ")");
    }
  }
}

// The rotation nearest to `block`, which must be within kPoseRotationTolerance
// of one.
Eigen::Matrix3d checked_rotation(const Eigen::Matrix3d& block) {
  const double off =
      (block.transpose() * block - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(off <= kPoseRotationTolerance) || block.determinant() <= 0) {
    throw std::invalid_argument(
        "the upper-left 3 x 3 is not a rotation (R^T R differs from the identity by " +
        number_text(off) + ", determinant " + number_text(block.determinant()) +
        "): it scales, shears or mirrors, and a scan's pose is a rigid motion. A matrix "
        "written in columns (OpenGL, 3DTK's .frames) must be transposed first");
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(block, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

ScanPose matrix_pose(const std::vector<double>& v) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = v[static_cast<std::size_t>(4 * r + c)];
  }
  if (m.row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    throw std::invalid_argument(
        "the last row of the 4 x 4 is " + number_text(m(3, 0)) + " " + number_text(m(3, 1)) + " " +
        number_text(m(3, 2)) + " " + number_text(m(3, 3)) +
        ", not 0 0 0 1: the matrix is written in rows, translation in the last column "
        "(transpose a matrix written in columns)");
  }
  ScanPose pose;
  pose.format = PoseFormat::kMatrix;
  pose.scan_to_scene.linear() = checked_rotation(m.topLeftCorner<3, 3>());
  pose.scan_to_scene.translation() = m.topRightCorner<3, 1>();
  return pose;
}

ScanPose tum_pose(const std::vector<double>& v) {
  const std::size_t first = v.size() == 8 ? 1 : 0;
  const Eigen::Quaterniond q(v[first + 6], v[first + 3], v[first + 4], v[first + 5]);
  if (!(std::fabs(q.norm() - 1.0) <= kPoseRotationTolerance)) {
    throw std::invalid_argument("the quaternion qx qy qz qw has length " + number_text(q.norm()) +
                                ", not 1: is the order [timestamp] tx ty tz qx qy qz qw?");
  }
  ScanPose pose;
  pose.format = PoseFormat::kTum;
  if (first == 1) pose.timestamp = v[0];
  pose.scan_to_scene.linear() = q.normalized().toRotationMatrix();
  pose.scan_to_scene.translation() = Eigen::Vector3d(v[first], v[first + 1], v[first + 2]);
  return pose;
}

double radians(double degrees) {
  return degrees * kPi / 180.0;
}
double degrees(double radians) {
  return radians * 180.0 / kPi;
}

ScanPose tdtk_pose(const std::vector<double>& v) {
  // Rx(ax) Ry(ay) Rz(az), in 3DTK's frame.
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(radians(v[3]), Eigen::Vector3d::UnitX()) *
                                    Eigen::AngleAxisd(radians(v[4]), Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(radians(v[5]), Eigen::Vector3d::UnitZ()))
                                       .toRotationMatrix();
  const Eigen::Matrix3d axes = from_3dtk_axes();
  ScanPose pose;
  pose.format = PoseFormat::k3dtk;
  pose.scan_to_scene.linear() = axes * rotation * axes.transpose();
  pose.scan_to_scene.translation() = point_from_3dtk(Eigen::Vector3d(v[0], v[1], v[2]));
  return pose;
}

// 3DTK's translation (cm) and Euler angles (degrees) of `pose`.
std::vector<double> tdtk_numbers(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d axes = from_3dtk_axes();
  const Eigen::Matrix3d r = axes.transpose() * pose.linear() * axes;
  const Eigen::Vector3d t = kCentimetresPerMetre * (axes.transpose() * pose.translation());
  // R = Rx Ry Rz: r(0,2) = sin ay, r(1,2) = -sin ax cos ay, r(2,2) = cos ax cos ay,
  // r(0,1) = -cos ay sin az, r(0,0) = cos ay cos az.
  const double cos_ay = std::hypot(r(0, 0), r(0, 1));
  const double ay = std::atan2(r(0, 2), cos_ay);
  double ax = 0, az = 0;
  if (cos_ay > 1e-12) {
    ax = std::atan2(-r(1, 2), r(2, 2));
    az = std::atan2(-r(0, 1), r(0, 0));
  } else {
    // Gimbal lock: only ax + az (or ax - az) is determined; az = 0 leaves
    // r(2,1) = sin ax, r(1,1) = cos ax.
    ax = std::atan2(r(2, 1), r(1, 1));
  }
  return {t.x(), t.y(), t.z(), degrees(ax), degrees(ay), degrees(az)};
}

// The numbers of `text`, line by line (blank and `#` lines skipped), with
// their line numbers.
struct NumberLine {
  std::size_t line = 0;
  std::vector<double> numbers;
};

std::vector<NumberLine> number_lines(const std::string& path, std::string_view text) {
  std::vector<NumberLine> result;
  detail::Lines lines(detail::without_byte_order_mark(text));
  std::string_view line;
  while (lines.next(line)) {
    const std::size_t comment = line.find('#');
    if (comment != std::string_view::npos) line = line.substr(0, comment);
    if (detail::is_blank_line(line)) continue;
    NumberLine numbers{lines.number(), {}};
    detail::Tokens tokens(line);
    for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
      double value = 0;
      if (!detail::parse_double(token, value)) {
        throw InputError(path, lines.number(),
                         detail::quoted(token) +
                             " is not a number: a pose file holds numbers only "
                             "(and `#` comment lines)");
      }
      numbers.numbers.push_back(value);
    }
    result.push_back(std::move(numbers));
  }
  return result;
}

std::size_t number_count(const std::vector<NumberLine>& lines) {
  std::size_t count = 0;
  for (const NumberLine& line : lines) count += line.numbers.size();
  return count;
}

std::string format_advice() {
  return "say which format it is (" + pose_format_names() +
         "; docs/formats.md, \"Poses\"): a project file's \"pose_format\", register's "
         "--pose-format (key pose_format), or a pose file's extension .pose for 3DTK";
}

}  // namespace

std::string_view pose_format_name(PoseFormat format) {
  switch (format) {
    case PoseFormat::kMatrix:
      return "matrix";
    case PoseFormat::kTum:
      return "tum";
    case PoseFormat::k3dtk:
      return "3dtk";
  }
  return "matrix";
}

std::optional<PoseFormat> pose_format_from_name(std::string_view name) {
  for (const PoseFormat format : {PoseFormat::kMatrix, PoseFormat::kTum, PoseFormat::k3dtk}) {
    if (name == pose_format_name(format)) return format;
  }
  return std::nullopt;
}

std::string pose_format_names() {
  return "matrix, tum, 3dtk";
}

ScanPose pose_from_numbers(const std::vector<double>& numbers, PoseFormat format) {
  const std::size_t n = numbers.size();
  switch (format) {
    case PoseFormat::kMatrix:
      if (n != 16) {
        throw std::invalid_argument("a 4 x 4 matrix is 16 numbers in rows, not " +
                                    std::to_string(n));
      }
      check_finite(numbers);
      return matrix_pose(numbers);
    case PoseFormat::kTum:
      if (n != 7 && n != 8) {
        throw std::invalid_argument(
            "a TUM pose is 7 numbers, tx ty tz qx qy qz qw (8 with a leading timestamp), not " +
            std::to_string(n));
      }
      check_finite(numbers);
      return tum_pose(numbers);
    case PoseFormat::k3dtk:
      if (n != 6) {
        throw std::invalid_argument(
            "a 3DTK pose is 6 numbers, tx ty tz (cm) then ax ay az (degrees), not " +
            std::to_string(n));
      }
      check_finite(numbers);
      return tdtk_pose(numbers);
  }
  throw std::invalid_argument("unknown pose format");
}

std::vector<double> pose_numbers(const ScanPose& pose) {
  const Eigen::Isometry3d& m = pose.scan_to_scene;
  switch (pose.format) {
    case PoseFormat::kMatrix: {
      std::vector<double> numbers;
      const Eigen::Matrix4d matrix = m.matrix();
      for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) numbers.push_back(matrix(r, c));
      }
      return numbers;
    }
    case PoseFormat::kTum: {
      const Eigen::Quaterniond q(m.linear());
      std::vector<double> numbers;
      if (pose.timestamp) numbers.push_back(*pose.timestamp);
      const Eigen::Vector3d t = m.translation();
      for (const double value : {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()}) {
        numbers.push_back(value);
      }
      return numbers;
    }
    case PoseFormat::k3dtk:
      return tdtk_numbers(m);
  }
  return {};
}

PoseFormat detect_pose_format(const std::string& path, std::string_view text) {
  if (detail::lower_extension(path) == ".pose") return PoseFormat::k3dtk;
  const std::vector<NumberLine> lines = number_lines(path, text);
  const std::size_t count = number_count(lines);
  if (count == 16) return PoseFormat::kMatrix;
  if (lines.size() == 1 && count == 8) return PoseFormat::kTum;
  std::string why;
  if (lines.size() > 1 && lines[0].numbers.size() == 8) {
    why = "it holds " + std::to_string(lines.size()) +
          " lines of 8 numbers, a TUM trajectory, and a scan has one pose: keep the line of "
          "the scan's time";
  } else if (count == 7) {
    why =
        "7 numbers are TUM's tx ty tz qx qy qz qw, or a quaternion with its w first, and "
        "nothing in them tells which";
  } else if (count == 6) {
    why =
        "6 numbers are 3DTK's translation in centimetres and angles in degrees, or metres "
        "and radians, or roll pitch yaw, and nothing in them tells which";
  } else {
    why = "it holds " + std::to_string(count) +
          " numbers; a pose is 16 (a 4 x 4 matrix in rows), 7 or 8 (TUM) or 6 (3DTK's .pose)";
  }
  throw InputError(path, 0, "cannot tell the pose's format: " + why + "; " + format_advice());
}

ScanPose read_pose_file(const std::string& path, std::optional<PoseFormat> format) {
  const std::string text = read_file_bytes(path);
  const PoseFormat chosen = format ? *format : detect_pose_format(path, text);
  const std::vector<NumberLine> lines = number_lines(path, text);
  if (lines.empty()) throw InputError(path, 0, "holds no pose (no numbers)");
  if (chosen == PoseFormat::kTum && lines.size() > 1) {
    throw InputError(path, lines[1].line,
                     "a TUM pose file for one scan holds one line; this one holds " +
                         std::to_string(lines.size()) +
                         " (a trajectory): keep the line of the scan's time");
  }
  std::vector<double> numbers;
  for (const NumberLine& line : lines) {
    numbers.insert(numbers.end(), line.numbers.begin(), line.numbers.end());
  }
  try {
    return pose_from_numbers(numbers, chosen);
  } catch (const std::invalid_argument& error) {
    throw InputError(
        path, 0,
        std::string(error.what()) + " (read as " + std::string(pose_format_name(chosen)) + ")");
  }
}

std::string pose_file_text(const ScanPose& pose) {
  const std::vector<double> numbers = pose_numbers(pose);
  // Numbers per line: a matrix's rows; 3DTK's translation, then its angles.
  std::size_t per_line = numbers.size();
  if (pose.format == PoseFormat::kMatrix) per_line = 4;
  if (pose.format == PoseFormat::k3dtk) per_line = 3;
  std::string text;
  if (pose.format == PoseFormat::kTum) {
    text += pose.timestamp ? "# timestamp tx ty tz qx qy qz qw\n" : "# tx ty tz qx qy qz qw\n";
  }
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    detail::append_number(text, numbers[i]);
    text += (i + 1) % per_line == 0 ? '\n' : ' ';
  }
  return text;
}

void write_pose_file(const std::string& path, const ScanPose& pose) {
  const std::string text = pose_file_text(pose);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

Eigen::Vector3d point_from_3dtk(const Eigen::Vector3d& point_cm) {
  return Eigen::Vector3d(point_cm.z(), -point_cm.x(), point_cm.y()) / kCentimetresPerMetre;
}

}  // namespace occlusion
