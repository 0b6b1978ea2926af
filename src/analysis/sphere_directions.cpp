#include "occlusion/analysis/sphere_directions.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "occlusion/core/random.hpp"
#include "occlusion/core/sampling.hpp"

namespace occlusion {

namespace {

// Separate families of streams, so that a viewpoint's rotation never shares a
// stream with one of its rays.
constexpr std::uint64_t kRayStreams = 0x5241595300000000ULL;       // "RAYS"
constexpr std::uint64_t kRotationStreams = 0x524f544100000000ULL;  // "ROTA"

}  // namespace

Eigen::Vector3d fibonacci_direction(std::size_t index, std::size_t count) {
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  const double n = static_cast<double>(count);
  const double i = static_cast<double>(index);
  // Band centres, so that no point sits on a pole and each band has area 4 pi / n.
  const double z = 1.0 - (2.0 * i + 1.0) / n;
  const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
  // The angle reduced before multiplying keeps precision for large indices.
  const double angle = std::fmod(i * golden_angle, 2.0 * M_PI);
  return {ring * std::cos(angle), ring * std::sin(angle), z};
}

Eigen::Matrix3d uniform_rotation(double u1, double u2, double u3) {
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const Eigen::Quaterniond q(b * std::cos(2.0 * M_PI * u3), a * std::sin(2.0 * M_PI * u2),
                             a * std::cos(2.0 * M_PI * u2), b * std::sin(2.0 * M_PI * u3));
  return q.normalized().toRotationMatrix();
}

SphereDirections::SphereDirections(DirectionSampling sampling, std::size_t count,
                                   std::uint64_t seed, std::size_t viewpoint)
    : sampling_(sampling), count_(count), seed_(seed), viewpoint_(viewpoint) {
  if (count == 0) throw std::invalid_argument("sphere directions: count must be > 0");
  Rng rng(seed, kRotationStreams + viewpoint);
  const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  rotation_ = uniform_rotation(u1, u2, u3);
}

Eigen::Vector3d SphereDirections::operator()(std::size_t index) const {
  if (sampling_ == DirectionSampling::kFibonacci) {
    return rotation_ * fibonacci_direction(index, count_);
  }
  // One stream per ray, so any block of rays can be drawn on its own: a 64-bit
  // hash of (viewpoint, index), whose collisions are negligible at any ray count.
  Rng rng(seed_,
          kRayStreams ^ mix64(static_cast<std::uint64_t>(viewpoint_) * 0x9e3779b97f4a7c15ULL +
                              static_cast<std::uint64_t>(index)));
  const double r1 = rng.uniform();
  const double r2 = rng.uniform();
  return sample_sphere_direction(r1, r2);
}

}  // namespace occlusion
