#include "surface_sampler.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace occlusion::room {

namespace {

constexpr double kNormalNoise = 0.001;   // metres, uniform either side of the surface
constexpr double kContactMargin = 0.01;  // a surface this close inside another box is hidden
constexpr int kPointColourJitter = 10;

}  // namespace

SurfaceSampler::SurfaceSampler(std::uint64_t seed, double spacing, double sensor_noise)
    : seed_(seed), spacing_(spacing), sensor_noise_(sensor_noise) {}

void SurfaceSampler::set_solids(const std::vector<Part>& parts) {
  solids_.clear();
  for (const Part& part : parts)
    solids_.insert(solids_.end(), part.boxes.begin(), part.boxes.end());
}

Instance& SurfaceSampler::start(std::vector<Instance>& instances, const std::string& class_name) {
  instances.push_back({class_name, {}});
  rng_ = Rng(seed_, instances.size());
  return instances.back();
}

Colour SurfaceSampler::jittered(const Colour& base, int jitter) {
  Colour colour;
  for (int c = 0; c < 3; ++c) {
    const int offset = static_cast<int>(std::floor(rng_.uniform() * (2 * jitter + 1))) - jitter;
    colour[c] = std::clamp(base[c] + offset, 0, 255);
  }
  return colour;
}

Eigen::Vector3d SurfaceSampler::sensor_offset() {
  // Box-Muller, one pair per axis (the second value is dropped: simpler
  // than carrying it, and the stream is ours).
  Eigen::Vector3d offset;
  for (int axis = 0; axis < 3; ++axis) {
    const double u = 1.0 - rng_.uniform();  // (0, 1]: log is finite
    const double v = rng_.uniform();
    offset[axis] = sensor_noise_ * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v);
  }
  return offset;
}

void SurfaceSampler::rectangle(Instance& instance, const Eigen::Vector3d& origin,
                               const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                               const Colour& colour, const std::vector<Box>& holes,
                               std::size_t own_box) {
  const Eigen::Vector3d normal = u.cross(v).normalized();
  const int cells_u = std::max(1, static_cast<int>(std::lround(u.norm() / spacing_)));
  const int cells_v = std::max(1, static_cast<int>(std::lround(v.norm() / spacing_)));
  for (int i = 0; i < cells_u; ++i) {
    for (int j = 0; j < cells_v; ++j) {
      const double a = (i + rng_.uniform()) / cells_u;
      const double b = (j + rng_.uniform()) / cells_v;
      const double noise = (2 * rng_.uniform() - 1) * kNormalNoise;
      const Eigen::Vector3d surface = origin + a * u + b * v;
      const Colour point_colour = jittered(colour, kPointColourJitter);
      if (hidden(surface, holes, own_box)) continue;
      Eigen::Vector3d position = surface + noise * normal;
      if (sensor_noise_ > 0) position += sensor_offset();
      instance.points.push_back({position, point_colour});
    }
  }
}

bool SurfaceSampler::hidden(const Eigen::Vector3d& p, const std::vector<Box>& holes,
                            std::size_t own_box) const {
  for (const Box& hole : holes) {
    if (hole.contains(p, 0)) return true;
  }
  for (std::size_t s = 0; s < solids_.size(); ++s) {
    if (s != own_box && solids_[s].contains(p, kContactMargin)) return true;
  }
  return false;
}

void SurfaceSampler::box(Instance& instance, std::size_t box, unsigned skipped,
                         const Colour& colour) {
  const Box& b = solids_[box];
  const Eigen::Vector3d size = b.hi - b.lo;
  const Eigen::Vector3d ex(size.x(), 0, 0);
  const Eigen::Vector3d ey(0, size.y(), 0);
  const Eigen::Vector3d ez(0, 0, size.z());
  const Eigen::Vector3d& lo = b.lo;
  if (!(skipped & kMinX)) rectangle(instance, lo, ez, ey, colour, {}, box);
  if (!(skipped & kMaxX)) rectangle(instance, lo + ex, ey, ez, colour, {}, box);
  if (!(skipped & kMinY)) rectangle(instance, lo, ex, ez, colour, {}, box);
  if (!(skipped & kMaxY)) rectangle(instance, lo + ey, ez, ex, colour, {}, box);
  if (!(skipped & kMinZ)) rectangle(instance, lo, ey, ex, colour, {}, box);
  if (!(skipped & kMaxZ)) rectangle(instance, lo + ez, ex, ey, colour, {}, box);
}

void SurfaceSampler::parts(std::vector<Instance>& instances, const std::vector<Part>& parts) {
  std::size_t solid = 0;
  for (const Part& part : parts) {
    Instance& instance = start(instances, part.class_name);
    for (std::size_t b = 0; b < part.boxes.size(); ++b, ++solid) {
      const unsigned skipped = b < part.skipped_faces.size() ? part.skipped_faces[b] : 0;
      box(instance, solid, skipped, part.colour);
    }
  }
}

}  // namespace occlusion::room
