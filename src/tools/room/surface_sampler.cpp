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
  Instance instance;
  instance.class_name = class_name;
  instances.push_back(std::move(instance));
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
  add_surface(instance, origin, u, v, holes);
}

void SurfaceSampler::add_surface(Instance& instance, const Eigen::Vector3d& origin,
                                 const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                 const std::vector<Box>& holes) const {
  // The rectangle cut along the outlines of the holes that cross its plane,
  // so each cell is wholly inside a hole or wholly outside every hole. No
  // random draw: the points stay as they were without --mesh.
  const Eigen::Vector3d normal = u.cross(v).normalized();
  std::vector<double> cuts_u{0.0, 1.0}, cuts_v{0.0, 1.0};
  for (const Box& hole : holes) {
    double lo_u = 1.0, hi_u = 0.0, lo_v = 1.0, hi_v = 0.0, lo_n = 0.0, hi_n = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d c((corner & 1) ? hole.hi.x() : hole.lo.x(),
                              (corner & 2) ? hole.hi.y() : hole.lo.y(),
                              (corner & 4) ? hole.hi.z() : hole.lo.z());
      const Eigen::Vector3d d = c - origin;
      const double a = d.dot(u) / u.squaredNorm(), b = d.dot(v) / v.squaredNorm();
      const double n = d.dot(normal);
      lo_u = corner == 0 ? a : std::min(lo_u, a);
      hi_u = corner == 0 ? a : std::max(hi_u, a);
      lo_v = corner == 0 ? b : std::min(lo_v, b);
      hi_v = corner == 0 ? b : std::max(hi_v, b);
      lo_n = corner == 0 ? n : std::min(lo_n, n);
      hi_n = corner == 0 ? n : std::max(hi_n, n);
    }
    if (lo_n > 0 || hi_n < 0) continue;  // the hole does not cross the surface
    for (const double a : {lo_u, hi_u}) {
      if (a > 0 && a < 1) cuts_u.push_back(a);
    }
    for (const double b : {lo_v, hi_v}) {
      if (b > 0 && b < 1) cuts_v.push_back(b);
    }
  }
  for (auto* cuts : {&cuts_u, &cuts_v}) {
    std::sort(cuts->begin(), cuts->end());
    cuts->erase(std::unique(cuts->begin(), cuts->end()), cuts->end());
  }
  for (std::size_t i = 0; i + 1 < cuts_u.size(); ++i) {
    for (std::size_t j = 0; j + 1 < cuts_v.size(); ++j) {
      const auto at = [&](double a, double b) -> Eigen::Vector3d { return origin + a * u + b * v; };
      const Eigen::Vector3d centre =
          at(0.5 * (cuts_u[i] + cuts_u[i + 1]), 0.5 * (cuts_v[j] + cuts_v[j + 1]));
      const bool in_hole = std::any_of(holes.begin(), holes.end(),
                                       [&](const Box& hole) { return hole.contains(centre, 0); });
      if (in_hole) continue;
      const Eigen::Vector3d p00 = at(cuts_u[i], cuts_v[j]), p10 = at(cuts_u[i + 1], cuts_v[j]);
      const Eigen::Vector3d p11 = at(cuts_u[i + 1], cuts_v[j + 1]),
                            p01 = at(cuts_u[i], cuts_v[j + 1]);
      instance.triangles.push_back({p00, p10, p11});
      instance.triangles.push_back({p00, p11, p01});
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
