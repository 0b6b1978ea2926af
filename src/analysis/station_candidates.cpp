#include "occlusion/analysis/station_candidates.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <thread>

#include "occlusion/analysis/inside_solid.hpp"
#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/sphere_octree.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

namespace {

// The probe directions: an unrotated Fibonacci lattice (fixed, evenly
// spread), cut to those at most kOutsideProbeTopDegrees above the horizontal.
std::vector<Eigen::Vector3f> probe_directions(const UpAxis& up) {
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  const Eigen::Vector3d up_vector = up.vector();
  const double top = std::sin(kOutsideProbeTopDegrees * M_PI / 180.0);
  std::vector<Eigen::Vector3f> directions;
  for (std::size_t k = 0; k < kOutsideProbeRays; ++k) {
    const double z = 1.0 - (2.0 * static_cast<double>(k) + 1.0) / kOutsideProbeRays;
    const double r = std::sqrt(1.0 - z * z);
    const double phi = golden * static_cast<double>(k);
    const Eigen::Vector3d d(r * std::cos(phi), r * std::sin(phi), z);
    if (d.dot(up_vector) <= top) directions.push_back(d.cast<float>());
  }
  return directions;
}

// Does the share of probe rays that escape `tree` exceed kOutsideEscapeShare?
template <class Tree>
bool escapes(const Tree& tree, const Eigen::Vector3d& position,
             const std::vector<Eigen::Vector3f>& directions) {
  std::size_t escaped = 0;
  for (const auto& direction : directions) {
    Ray ray;
    ray.origin = position.cast<float>();
    ray.direction = direction;
    if (!tree.occluded(ray)) ++escaped;
  }
  return static_cast<double>(escaped) >
         kOutsideEscapeShare * static_cast<double>(directions.size());
}

// Squared distance from p to triangle abc (Ericson, Real-Time Collision
// Detection 5.1.5: the closest point by Voronoi region).
double squared_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    return (p - (a + d1 / (d1 - d3) * ab)).squaredNorm();
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    return (p - (a + d2 / (d2 - d6) * ac)).squaredNorm();
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).squaredNorm();
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return (p - (a + ab * v + ac * w)).squaredNorm();
}

// Face tests between two progress reports of clear_of_faces: a few
// milliseconds. A report is where Python polls for Ctrl-C, and a fine grid
// over a large mesh takes seconds.
constexpr std::size_t kFaceTestsPerReport = std::size_t{1} << 22;

// A face with its box grown by the clearance (a quick rejection).
struct ClearanceFace {
  Eigen::Vector3d a, b, c, lo, hi;
};

std::vector<ClearanceFace> clearance_faces(const TriangleMesh& mesh, double clearance) {
  std::vector<ClearanceFace> faces(mesh.face_count());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& v = mesh.faces[f];
    ClearanceFace& face = faces[f];
    face.a = mesh.vertices[v[0]];
    face.b = mesh.vertices[v[1]];
    face.c = mesh.vertices[v[2]];
    face.lo = face.a.cwiseMin(face.b).cwiseMin(face.c).array() - clearance;
    face.hi = face.a.cwiseMax(face.b).cwiseMax(face.c).array() + clearance;
  }
  return faces;
}

// Positions with nothing nearer than `clearance` among the mesh's faces.
std::vector<bool> clear_of_faces(const std::vector<ClearanceFace>& faces,
                                 const std::vector<Eigen::Vector3d>& positions, double clearance,
                                 unsigned threads, const Progress& progress) {
  const double limit = clearance * clearance;
  std::vector<char> clear(positions.size(), 1);
  std::atomic<bool> cancelled{false};
  // The calling thread, one of the workers, reports.
  const std::thread::id caller = std::this_thread::get_id();
  const std::size_t positions_per_report =
      std::max<std::size_t>(1, kFaceTestsPerReport / std::max<std::size_t>(1, faces.size()));
  std::atomic<std::size_t> done{0};
  std::size_t next_report = positions_per_report;
  progress("clearance", 0.0);
  parallel_for(positions.size(), 16, threads, [&](std::size_t begin, std::size_t end) {
    if (progress.cancel != nullptr && progress.cancel->load()) {
      cancelled = true;
      return;
    }
    for (std::size_t i = begin; i < end; ++i) {
      const Eigen::Vector3d& p = positions[i];
      for (const ClearanceFace& face : faces) {
        if ((p.array() < face.lo.array()).any() || (p.array() > face.hi.array()).any()) continue;
        if (squared_distance(p, face.a, face.b, face.c) < limit) {
          clear[i] = 0;
          break;
        }
      }
    }
    const std::size_t finished = done.fetch_add(end - begin) + (end - begin);
    if (finished >= next_report && std::this_thread::get_id() == caller) {
      next_report = finished + positions_per_report;
      progress("clearance", static_cast<double>(finished) / static_cast<double>(positions.size()));
    }
  });
  if (cancelled) throw Cancelled();
  return {clear.begin(), clear.end()};
}

// A cloud's points by cells of the clearance's size: every point nearer
// than the clearance to a position lies in its cell or one of the 26 around
// it. Built once, asked for a few positions at a time by a refinement as for
// a grid of thousands.
class PointCells {
 public:
  PointCells(const PointCloud& cloud, double clearance)
      : points_(cloud.positions), cell_(clearance) {
    if (clearance <= 0.0) return;
    entries_.reserve(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      entries_.push_back(
          {key(cell_of(cloud.positions[i].cast<double>())), static_cast<std::uint32_t>(i)});
    }
    std::sort(entries_.begin(), entries_.end());
  }

  // Is a point nearer than the clearance to p?
  bool near(const Eigen::Vector3d& p) const {
    if (cell_ <= 0.0) return false;
    const Eigen::Array3d centre = cell_of(p);
    const double limit = cell_ * cell_;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const std::uint64_t k = key(centre + Eigen::Array3d(dx, dy, dz));
          auto it = std::lower_bound(entries_.begin(), entries_.end(), Entry{k, 0});
          for (; it != entries_.end() && it->first == k; ++it) {
            if ((points_[it->second].cast<double>() - p).squaredNorm() < limit) return true;
          }
        }
      }
    }
    return false;
  }

 private:
  using Entry = std::pair<std::uint64_t, std::uint32_t>;
  Eigen::Array3d cell_of(const Eigen::Vector3d& p) const { return (p.array() / cell_).floor(); }
  // Cells hash to 64 bits; two that collide share a run, which the distance test sorts out.
  static std::uint64_t key(const Eigen::Array3d& cell) {
    std::uint64_t h = 0;
    for (int axis = 0; axis < 3; ++axis) {
      h = (h ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(cell[axis]))) *
          0x9E3779B97F4A7C15ull;
    }
    return h;
  }

  const std::vector<Eigen::Vector3f>& points_;
  double cell_;
  std::vector<Entry> entries_;
};

// Positions between two progress reports of the probes.
constexpr std::size_t kProbedPerReport = 64;

// `in_solid` (meshes; null for clouds) probes a position that is clear, in
// the same loop as the outside probes, so that cancel and progress are
// checked between positions for both. Positions are probed on `threads`
// threads (a few hundred single rays each: 100,000 took 30 s on one), the
// calling thread reporting; the kept ones stay in their order.
// `seen_empty` (clouds with stations; else null) keeps a position the probes
// call outside.
template <class Tree>
StationCandidates keep(std::vector<Eigen::Vector3d> positions, const std::vector<bool>& clear,
                       const std::function<bool(const Eigen::Vector3d&)>& in_solid,
                       const std::function<bool(const Eigen::Vector3d&)>& seen_empty,
                       const Tree& tree, const std::vector<Eigen::Vector3f>& directions,
                       unsigned threads, const Progress& progress) {
  enum Verdict : std::uint8_t { kKept, kClearance, kInsideSolid, kOutside };
  std::vector<std::uint8_t> verdict(positions.size(), kKept);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<std::size_t> done{0};
  std::size_t next_report = 0;
  parallel_for(positions.size(), 16, threads, [&](std::size_t begin, std::size_t end) {
    progress.check_cancel();
    for (std::size_t i = begin; i < end; ++i) {
      if (!clear[i]) {
        verdict[i] = kClearance;
      } else if (in_solid && in_solid(positions[i])) {
        verdict[i] = kInsideSolid;
      } else if (escapes(tree, positions[i], directions) &&
                 !(seen_empty && seen_empty(positions[i]))) {
        verdict[i] = kOutside;
      }
    }
    const std::size_t finished = done.fetch_add(end - begin) + (end - begin);
    if (finished >= next_report && std::this_thread::get_id() == caller) {
      next_report = finished + kProbedPerReport;
      progress("candidates", static_cast<double>(finished) / static_cast<double>(positions.size()));
    }
  });
  progress.check_cancel();
  StationCandidates result;
  result.tested = positions.size();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    switch (verdict[i]) {
      case kClearance:
        ++result.rejected.clearance;
        break;
      case kInsideSolid:
        ++result.rejected.inside_solid;
        break;
      case kOutside:
        ++result.rejected.outside;
        break;
      default:
        result.positions.push_back(positions[i]);
    }
  }
  return result;
}

void check_positions(const std::vector<Eigen::Vector3d>& positions, double clearance) {
  if (!(clearance >= 0.0) || !std::isfinite(clearance)) {
    throw std::invalid_argument("station candidates: the clearance must be >= 0");
  }
  for (const auto& p : positions) {
    if (!p.allFinite()) throw std::invalid_argument("station candidates: a position is not finite");
  }
}

// Does a station's line of sight pass through `position` to a point beyond
// it? The segment from the station is clear, and the ray on meets the scene.
template <class Tree>
bool seen_empty_from(const Tree& tree, const std::vector<Eigen::Vector3d>& stations,
                     const Eigen::Vector3d& position) {
  for (const auto& station : stations) {
    const Eigen::Vector3d offset = position - station;
    const double distance = offset.norm();
    if (!(distance > 0.0)) return true;
    Ray ray;
    ray.origin = station.cast<float>();
    ray.direction = (offset / distance).cast<float>();
    ray.t_max = static_cast<float>(distance);
    if (tree.occluded(ray)) continue;
    ray.t_min = ray.t_max;
    ray.t_max = std::numeric_limits<float>::infinity();
    if (tree.occluded(ray)) return true;
  }
  return false;
}

}  // namespace

double auto_grid_spacing(const Box& frame, const UpAxis& up) {
  const int a = up.axis, u = (a + 1) % 3, v = (a + 2) % 3;
  const double eu = frame.hi[u] - frame.lo[u], ev = frame.hi[v] - frame.lo[v];
  const double n = static_cast<double>(kAutoGridPositions);
  double spacing = std::sqrt(eu * ev / n);
  // A floor plan that is a line: its length over the positions.
  if (!(spacing > 0.0)) spacing = std::max(eu, ev) / n;
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    throw std::invalid_argument("station candidates: the frame has no extent across up");
  }
  return spacing;
}

std::vector<Eigen::Vector3d> floor_grid(const Box& frame, const UpAxis& up, double spacing,
                                        double height) {
  if (!(spacing > 0.0) || !std::isfinite(spacing) || !(height > 0.0) || !std::isfinite(height)) {
    throw std::invalid_argument("station candidates: spacing and height must be > 0");
  }
  const int a = up.axis, u = (a + 1) % 3, v = (a + 2) % 3;
  const double floor = up.sign > 0 ? frame.lo[a] : -frame.hi[a];
  const double top = up.sign > 0 ? frame.hi[a] : -frame.lo[a];
  if (floor + height > top) {
    throw std::invalid_argument("station candidates: the height " + std::to_string(height) +
                                " is above the scene (" + std::to_string(top - floor) + " high)");
  }
  // Steps that fit along each floor axis, the grid centred between the walls.
  const auto steps = [&](int axis) {
    const double extent = frame.hi[axis] - frame.lo[axis];
    return std::floor(extent / spacing) + 1.0;
  };
  const double nu = steps(u), nv = steps(v);
  if (nu * nv > static_cast<double>(kMaxCandidates)) {
    throw std::invalid_argument("station candidates: spacing " + std::to_string(spacing) +
                                " gives " + std::to_string(nu * nv) +
                                " grid positions, more than " + std::to_string(kMaxCandidates));
  }
  const double start_u = (frame.lo[u] + frame.hi[u] - (nu - 1.0) * spacing) / 2.0;
  const double start_v = (frame.lo[v] + frame.hi[v] - (nv - 1.0) * spacing) / 2.0;
  std::vector<Eigen::Vector3d> positions;
  for (std::size_t j = 0; j < static_cast<std::size_t>(nv); ++j) {
    for (std::size_t i = 0; i < static_cast<std::size_t>(nu); ++i) {
      Eigen::Vector3d p;
      p[a] = up.sign * (floor + height);
      p[u] = start_u + static_cast<double>(i) * spacing;
      p[v] = start_v + static_cast<double>(j) * spacing;
      positions.push_back(p);
    }
  }
  return positions;
}

struct FreeSpace::Impl {
  double clearance = 0.0;
  unsigned threads = 0;
  std::vector<Eigen::Vector3f> directions;
  // A cloud's: its point cells, its probe spheres and stations.
  std::unique_ptr<PointCells> cells;
  std::unique_ptr<SphereOctree> spheres;
  std::vector<Eigen::Vector3d> stations;
  // A mesh's: its faces for the clearance, and its octree.
  std::vector<ClearanceFace> faces;
  std::unique_ptr<TriangleOctree> triangles;
};

FreeSpace::FreeSpace(const PointCloud& cloud, double clearance, const UpAxis& up,
                     std::vector<Eigen::Vector3d> stations, unsigned threads,
                     const Progress& progress)
    : impl_(std::make_unique<Impl>()) {
  if (cloud.size() == 0) throw std::invalid_argument("station candidates: the cloud is empty");
  check_positions({}, clearance);
  impl_->clearance = clearance;
  impl_->threads = threads;
  impl_->directions = probe_directions(up);
  impl_->cells = std::make_unique<PointCells>(cloud, clearance);
  const double radius = kProbeRadiusPerSpacing * measure_point_spacing(cloud, threads).spacing;
  impl_->spheres = std::make_unique<SphereOctree>(
      make_spheres(cloud.positions, static_cast<float>(radius)), sphere_octree_options(), progress);
  impl_->stations = std::move(stations);
}

FreeSpace::FreeSpace(const TriangleMesh& mesh, double clearance, const UpAxis& up, unsigned threads,
                     const Progress& progress)
    : impl_(std::make_unique<Impl>()) {
  if (mesh.face_count() == 0)
    throw std::invalid_argument("station candidates: the mesh has no faces");
  check_positions({}, clearance);
  impl_->clearance = clearance;
  impl_->threads = threads;
  impl_->directions = probe_directions(up);
  impl_->faces = clearance_faces(mesh, clearance);
  impl_->triangles =
      std::make_unique<TriangleOctree>(pack_triangles(mesh.triangles()), OctreeOptions{}, progress);
}

FreeSpace::~FreeSpace() = default;
FreeSpace::FreeSpace(FreeSpace&&) noexcept = default;
FreeSpace& FreeSpace::operator=(FreeSpace&&) noexcept = default;

StationCandidates FreeSpace::keep(std::vector<Eigen::Vector3d> positions,
                                  const Progress& progress) const {
  const Impl& s = *impl_;
  check_positions(positions, s.clearance);
  if (s.triangles) {
    const std::vector<bool> clear =
        clear_of_faces(s.faces, positions, s.clearance, s.threads, progress);
    const auto in_solid = [&](const Eigen::Vector3d& position) {
      return back_face_shares(*s.triangles, {position}).front() > kInsideBackFaceShare;
    };
    return occlusion::keep(std::move(positions), clear, in_solid, nullptr, *s.triangles,
                           s.directions, s.threads, progress);
  }
  std::vector<bool> clear(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) clear[i] = !s.cells->near(positions[i]);
  std::function<bool(const Eigen::Vector3d&)> seen_empty;
  if (!s.stations.empty()) {
    seen_empty = [&](const Eigen::Vector3d& p) {
      return seen_empty_from(*s.spheres, s.stations, p);
    };
  }
  return occlusion::keep(std::move(positions), clear, nullptr, seen_empty, *s.spheres, s.directions,
                         s.threads, progress);
}

StationCandidates keep_free_positions(const PointCloud& cloud,
                                      std::vector<Eigen::Vector3d> positions, double clearance,
                                      const UpAxis& up, unsigned threads,
                                      const Progress& progress) {
  return FreeSpace(cloud, clearance, up, {}, threads, progress)
      .keep(std::move(positions), progress);
}

StationCandidates keep_free_positions(const TriangleMesh& mesh,
                                      std::vector<Eigen::Vector3d> positions, double clearance,
                                      const UpAxis& up, unsigned threads,
                                      const Progress& progress) {
  return FreeSpace(mesh, clearance, up, threads, progress).keep(std::move(positions), progress);
}

}  // namespace occlusion
