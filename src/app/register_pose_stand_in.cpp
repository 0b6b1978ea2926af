// TEMPORARY STAND-IN for io/pose_file.hpp: see register_pose_stand_in.hpp.

#include "register_pose_stand_in.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::pose_stand_in {

ScanPose read_pose_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open the pose file");
  std::vector<double> numbers;
  std::string token;
  while (in >> token) {
    try {
      std::size_t used = 0;
      numbers.push_back(std::stod(token, &used));
      if (used != token.size()) throw std::invalid_argument(token);
    } catch (const std::exception&) {
      throw InputError(path, 0, "'" + token + "' is not a number (a 4 x 4 matrix in rows)");
    }
  }
  if (numbers.size() != 16) {
    throw InputError(
        path, 0,
        std::to_string(numbers.size()) + " numbers; a pose is a 4 x 4 matrix in rows (16 numbers)");
  }
  Eigen::Matrix4d m;
  for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = numbers[i];
  if (!m.allFinite() || (m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 0) {
    throw InputError(path, 0, "the last row must be 0 0 0 1 and every number finite");
  }
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-3 ||
      r.determinant() < 0) {
    throw InputError(path, 0, "the upper 3 x 3 block is no rotation (a scale, shear or mirror)");
  }
  ScanPose pose;
  pose.scan_to_scene.linear() = Eigen::Quaterniond(r).normalized().toRotationMatrix();
  pose.scan_to_scene.translation() = m.topRightCorner<3, 1>();
  return pose;
}

void write_pose_file(const std::string& path, const ScanPose& pose) {
  std::ostringstream text;
  const Eigen::Matrix4d m = pose.scan_to_scene.matrix();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      char number[40];
      std::snprintf(number, sizeof number, "%.17g", m(r, c));
      text << number << (c == 3 ? "\n" : " ");
    }
  }
  OutputSet outputs;
  std::ofstream out(outputs.add(path));
  out << text.str();
  out.close();
  if (!out) throw OutputError(path, "cannot write the pose");
  outputs.commit();
}

}  // namespace occlusion::pose_stand_in
