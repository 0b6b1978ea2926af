#include "occlusion/analysis/virtual_scanner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "analysis_support.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

namespace {

using analysis_support::Clock;
using analysis_support::seconds_since;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
// Beams traced at a time: bounds the rays and hits held (a full-dome station
// of 0.2 degree steps is 1.35 M beams, times the sub-rays of a wide beam).
constexpr std::size_t kRaysPerBlock = 1 << 18;
// Beams made and turned into returns at a time by one thread.
constexpr std::size_t kGrain = 1024;

// A standard normal deviate from two uniforms (Box-Muller): fully specified,
// as Rng is, so a seed gives the same noise everywhere.
double standard_normal(Rng& rng) {
  const double u1 = 1.0 - rng.uniform();  // (0, 1]: the log is finite
  const double u2 = rng.uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

// One noise stream per beam of every station, so the answer does not depend
// on how beams are split among threads.
Rng beam_rng(std::uint64_t seed, std::size_t station, std::size_t beam) {
  return Rng(seed, (static_cast<std::uint64_t>(station) << 40) ^ beam);
}

// The beam's sub-ray offsets in its footprint, as fractions of the half
// divergence: the centre, then a sunflower spiral that fills the disc evenly.
std::vector<Eigen::Vector2d> footprint_offsets(unsigned samples) {
  std::vector<Eigen::Vector2d> offsets{Eigen::Vector2d::Zero()};
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (unsigned k = 1; k < samples; ++k) {
    const double radius = std::sqrt(static_cast<double>(k) / static_cast<double>(samples - 1));
    const double angle = golden * static_cast<double>(k);
    offsets.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  return offsets;
}

// What a block of beams of one station needs to turn hits into returns.
struct BeamGeometry {
  // Per beam: its central unit direction (laser) or its pixel ray with z = 1
  // in the camera frame (camera: t is then the depth), in the mesh's frame.
  std::vector<Eigen::Vector3d> directions;
  std::vector<std::uint32_t> cells;
};

// What became of a beam.
enum class Outcome : std::uint8_t { kPoint, kNoHit, kOutOfRange, kGrazing };

struct Return {
  Outcome outcome = Outcome::kNoHit;
  Eigen::Vector3d position;
  Eigen::Vector3f true_point, true_normal;
  std::uint32_t face = 0;
};

// The face's unit normal, turned to face the ray.
Eigen::Vector3f facing_normal(const PackedTriangle& tri, const Eigen::Vector3f& direction) {
  Eigen::Vector3f n = tri.normal / tri.normal_length;
  return n.dot(direction) > 0.0f ? Eigen::Vector3f(-n) : n;
}

class StationTracer {
 public:
  StationTracer(const TriangleOctree& octree, const std::vector<PackedTriangle>& by_face,
                const SimulationOptions& options)
      : octree_(octree), by_face_(by_face), options_(options) {}

  // Traces `rays` (sub_rays per beam) and returns their hits.
  std::vector<std::optional<Hit>> trace(const std::vector<Ray>& rays) const {
    std::vector<std::optional<Hit>> hits(rays.size());
    octree_.intersect_batch(rays.data(), rays.size(), nullptr, hits.data(), options_.threads);
    return hits;
  }

  const PackedTriangle& face(PrimitiveId id) const { return by_face_[id]; }
  const SimulationOptions& options() const { return options_; }

 private:
  const TriangleOctree& octree_;
  const std::vector<PackedTriangle>& by_face_;
  const SimulationOptions& options_;
};

// The laser's returns for one block of beams.
void laser_returns(const LaserScannerModel& model, const StationTracer& tracer,
                   const Eigen::Vector3d& origin, std::size_t station, const BeamGeometry& beams,
                   const std::vector<Eigen::Vector2d>& footprint, std::vector<Return>& out) {
  const std::size_t subs = footprint.size();
  const double half_angle = 0.5e-3 * model.beam_divergence_mrad;
  const Eigen::Vector3f origin_f = origin.cast<float>();
  std::vector<Ray> rays(beams.directions.size() * subs);
  const unsigned threads = tracer.options().threads;
  parallel_for(beams.directions.size(), kGrain, threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; ++b) {
      const Eigen::Vector3d& d = beams.directions[b];
      const Eigen::Vector3d u = d.unitOrthogonal();
      const Eigen::Vector3d v = d.cross(u);
      for (std::size_t s = 0; s < subs; ++s) {
        const Eigen::Vector2d& o = footprint[s];
        Eigen::Vector3d dir = d;
        const double radius = o.norm();
        if (radius > 0.0) dir += std::tan(half_angle * radius) / radius * (o.x() * u + o.y() * v);
        dir.normalize();
        Ray& ray = rays[b * subs + s];
        ray.origin = origin_f;
        ray.direction = dir.cast<float>();
        ray.t_min = 0.0f;
        ray.t_max = static_cast<float>(model.max_range);
      }
    }
  });
  const std::vector<std::optional<Hit>> hits = tracer.trace(rays);
  const double cos_limit = std::cos(tracer.options().max_incidence_deg * kDegree);
  out.assign(beams.directions.size(), Return{});
  parallel_for(
      beams.directions.size(), kGrain, threads, [&](std::size_t first_beam, std::size_t last_beam) {
        for (std::size_t b = first_beam; b < last_beam; ++b) {
          // The first echo, and the echoes a pulse could not tell from it.
          std::size_t nearest = subs;
          for (std::size_t s = 0; s < subs; ++s) {
            const auto& hit = hits[b * subs + s];
            if (hit && (nearest == subs || hit->t_hit < hits[b * subs + nearest]->t_hit))
              nearest = s;
          }
          if (nearest == subs) continue;  // no hit
          const Hit& first = *hits[b * subs + nearest];
          double range_sum = 0.0;
          std::size_t merged = 0;
          for (std::size_t s = 0; s < subs; ++s) {
            const auto& hit = hits[b * subs + s];
            if (hit && hit->t_hit <= first.t_hit + model.echo_window) {
              range_sum += hit->t_hit;
              ++merged;
            }
          }
          const double range = range_sum / static_cast<double>(merged);
          const Ray& ray = rays[b * subs + nearest];
          const PackedTriangle& tri = tracer.face(first.primitive_id);
          const Eigen::Vector3f normal = facing_normal(tri, ray.direction);
          if (-normal.dot(ray.direction) < cos_limit) {
            out[b].outcome = Outcome::kGrazing;
            continue;
          }
          if (range < model.min_range) {
            out[b].outcome = Outcome::kOutOfRange;
            continue;
          }
          Rng rng = beam_rng(tracer.options().seed, station, beams.cells[b]);
          const double measured = tracer.options().noise
                                      ? range + model.range_sigma(range) * standard_normal(rng)
                                      : range;
          Return& r = out[b];
          r.outcome = Outcome::kPoint;
          r.position = origin + measured * beams.directions[b];
          r.true_point = ray.at(first.t_hit);
          r.true_normal = normal;
          r.face = first.primitive_id;
        }
      });
}

// The camera's returns for one block of pixels.
void camera_returns(const DepthCameraModel& model, const StationTracer& tracer,
                    const Eigen::Vector3d& origin, std::size_t station, const BeamGeometry& beams,
                    std::vector<Return>& out) {
  const Eigen::Vector3f origin_f = origin.cast<float>();
  std::vector<Ray> rays(beams.directions.size());
  const unsigned threads = tracer.options().threads;
  for (std::size_t b = 0; b < rays.size(); ++b) {
    rays[b].origin = origin_f;
    rays[b].direction = beams.directions[b].cast<float>();  // z = 1 in the camera: t is depth
    rays[b].t_min = 0.0f;
    rays[b].t_max = static_cast<float>(model.max_depth);
  }
  const std::vector<std::optional<Hit>> hits = tracer.trace(rays);
  const double cos_limit = std::cos(tracer.options().max_incidence_deg * kDegree);
  out.assign(rays.size(), Return{});
  parallel_for(rays.size(), kGrain, threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; ++b) {
      if (!hits[b]) continue;
      const double depth = hits[b]->t_hit;
      const PackedTriangle& tri = tracer.face(hits[b]->primitive_id);
      const Eigen::Vector3f unit = rays[b].direction.normalized();
      const Eigen::Vector3f normal = facing_normal(tri, unit);
      if (-normal.dot(unit) < cos_limit) {
        out[b].outcome = Outcome::kGrazing;
        continue;
      }
      double measured = depth;
      if (tracer.options().noise) {
        Rng rng = beam_rng(tracer.options().seed, station, beams.cells[b]);
        measured = model.quantised_depth(depth + model.depth_sigma(depth) * standard_normal(rng));
      }
      if (depth < model.min_depth || measured < model.min_depth || measured > model.max_depth) {
        out[b].outcome = Outcome::kOutOfRange;
        continue;
      }
      Return& r = out[b];
      r.outcome = Outcome::kPoint;
      r.position = origin + measured * beams.directions[b];
      r.true_point = rays[b].at(hits[b]->t_hit);
      r.true_normal = normal;
      r.face = hits[b]->primitive_id;
    }
  });
}

void check_finite(const ScannerStation& station) {
  if (!station.position.allFinite() || !station.orientation.coeffs().allFinite() ||
      std::abs(station.orientation.norm() - 1.0) > 1e-3) {
    throw std::invalid_argument("virtual scanner: station '" + station.name +
                                "' has no finite position or no unit orientation");
  }
}

}  // namespace

std::string class_of_group(const std::string& group_name) {
  const std::size_t underscore = group_name.rfind('_');
  if (underscore == std::string::npos || underscore == 0 || underscore + 1 == group_name.size()) {
    return group_name;
  }
  for (std::size_t i = underscore + 1; i < group_name.size(); ++i) {
    if (group_name[i] < '0' || group_name[i] > '9') return group_name;
  }
  return group_name.substr(0, underscore);
}

Eigen::Quaterniond camera_looking_at(const Eigen::Vector3d& position, const Eigen::Vector3d& target,
                                     const Eigen::Vector3d& up) {
  const Eigen::Vector3d forward = target - position;
  if (!(forward.norm() > 0.0) || !forward.allFinite()) {
    throw std::invalid_argument("a camera cannot look at its own position");
  }
  const Eigen::Vector3d z = forward.normalized();
  const Eigen::Vector3d right = z.cross(up);
  if (right.norm() < 1e-9) {
    throw std::invalid_argument("a camera looking straight along the up axis has no image up");
  }
  const Eigen::Vector3d x = right.normalized();
  const Eigen::Vector3d y = z.cross(x);  // image down
  Eigen::Matrix3d rotation;
  rotation.col(0) = x;
  rotation.col(1) = y;
  rotation.col(2) = z;
  return Eigen::Quaterniond(rotation).normalized();
}

SimulatedScan simulate_scan(const TriangleMesh& mesh, const std::vector<ScannerStation>& stations,
                            const SensorModel& sensor, const SimulationOptions& options,
                            const Progress& progress) {
  mesh.validate();
  if (mesh.face_count() == 0) throw std::invalid_argument("virtual scanner: the mesh has no faces");
  if (stations.empty()) throw std::invalid_argument("virtual scanner: no stations");
  for (const auto& station : stations) check_finite(station);
  std::visit([](const auto& model) { validate(model); }, sensor);
  if (!(options.max_incidence_deg > 0.0 && options.max_incidence_deg <= 90.0)) {
    throw std::invalid_argument("virtual scanner: max_incidence must be in (0, 90] degrees");
  }
  const auto* laser = std::get_if<LaserScannerModel>(&sensor);
  const auto* camera = std::get_if<DepthCameraModel>(&sensor);

  SimulatedScan scan;
  PointCloud& cloud = scan.cloud;
  cloud.shift = choose_global_shift(mesh.vertices.front());

  auto start = Clock::now();
  progress("octree", 0.0);
  LargeVector<PackedTriangle> packed = pack_triangles(mesh, cloud.shift);
  const std::vector<PackedTriangle> by_face(packed.begin(), packed.end());
  const TriangleOctree octree(std::move(packed), OctreeOptions{}, progress);
  scan.build_seconds = seconds_since(start);
  const StationTracer tracer(octree, by_face, options);

  // Classes and instances from the groups.
  std::vector<std::int32_t> group_label(mesh.group_names.size());
  std::unordered_map<std::string, std::int32_t> class_ids;
  for (std::size_t g = 0; g < mesh.group_names.size(); ++g) {
    const std::string name = class_of_group(mesh.group_names[g]);
    const auto found = class_ids.emplace(name, static_cast<std::int32_t>(cloud.class_names.size()));
    if (found.second) cloud.class_names.push_back(name);
    group_label[g] = found.first->second;
  }

  const std::vector<Eigen::Vector2d> footprint = footprint_offsets(
      laser != nullptr && laser->beam_divergence_mrad > 0.0 ? laser->beam_samples : 1);
  const std::size_t columns = laser ? laser->columns() : camera->width;
  const std::size_t rows = laser ? laser->rows() : camera->height;
  const std::size_t cells = columns * rows;
  if (cells > std::size_t{1} << 32) {
    throw std::invalid_argument("virtual scanner: more than 2^32 beams a station");
  }
  // The laser's angles, once: a full dome at 0.1 degrees is 5.4 M beams.
  std::vector<double> cos_azimuth, sin_azimuth, cos_elevation, sin_elevation;
  if (laser) {
    for (std::size_t column = 0; column < columns; ++column) {
      cos_azimuth.push_back(std::cos(laser->azimuth_deg(column) * kDegree));
      sin_azimuth.push_back(std::sin(laser->azimuth_deg(column) * kDegree));
    }
    for (std::size_t row = 0; row < rows; ++row) {
      cos_elevation.push_back(std::cos(laser->elevation_deg(row) * kDegree));
      sin_elevation.push_back(std::sin(laser->elevation_deg(row) * kDegree));
    }
  }
  start = Clock::now();
  scan.per_station.resize(stations.size());
  for (std::size_t s = 0; s < stations.size(); ++s) {
    const ScannerStation& station = stations[s];
    const Eigen::Vector3d origin = station.position - cloud.shift;
    const Eigen::Matrix3d rotation = station.orientation.normalized().toRotationMatrix();
    Station recorded;
    recorded.name = station.name;
    recorded.frame.origin = origin;
    recorded.frame.orientation = station.orientation.normalized();
    if (laser) {
      recorded.frame.width = columns;
      recorded.frame.height = rows;
    }
    cloud.stations.push_back(recorded);

    BeamCounts& counts = scan.per_station[s];
    const std::size_t block = std::max<std::size_t>(kGrain, kRaysPerBlock / footprint.size());
    for (std::size_t first = 0; first < cells; first += block) {
      progress.check_cancel();
      progress("scanning",
               (static_cast<double>(s) + static_cast<double>(first) / static_cast<double>(cells)) /
                   static_cast<double>(stations.size()));
      const std::size_t last = std::min(cells, first + block);
      BeamGeometry beams;
      beams.directions.resize(last - first);
      beams.cells.resize(last - first);
      parallel_for(last - first, kGrain, options.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t b = begin; b < end; ++b) {
          const std::size_t cell = first + b;
          const std::size_t row = cell / columns, column = cell % columns;
          Eigen::Vector3d local;
          if (laser) {
            local = {cos_elevation[row] * cos_azimuth[column],
                     cos_elevation[row] * sin_azimuth[column], sin_elevation[row]};
          } else {
            local = {(static_cast<double>(column) - camera->principal_x()) / camera->fx,
                     (static_cast<double>(row) - camera->principal_y()) / camera->fy, 1.0};
          }
          beams.directions[b] = rotation * local;
          beams.cells[b] = static_cast<std::uint32_t>(cell);
        }
      });
      std::vector<Return> returns;
      if (laser) {
        laser_returns(*laser, tracer, origin, s, beams, footprint, returns);
      } else {
        camera_returns(*camera, tracer, origin, s, beams, returns);
      }
      for (std::size_t b = 0; b < returns.size(); ++b) {
        const Return& r = returns[b];
        ++counts.beams;
        if (r.outcome == Outcome::kNoHit) ++counts.no_hit;
        if (r.outcome == Outcome::kOutOfRange) ++counts.out_of_range;
        if (r.outcome == Outcome::kGrazing) ++counts.grazing;
        if (r.outcome != Outcome::kPoint) continue;
        ++counts.returns;
        cloud.positions.push_back(r.position.cast<float>());
        const std::uint32_t group = mesh.face_group[r.face];
        cloud.labels.push_back(group_label[group]);
        cloud.instances.push_back(static_cast<std::int32_t>(group));
        cloud.station_ids.push_back(static_cast<std::int32_t>(s));
        scan.true_points.push_back(r.true_point);
        scan.true_normals.push_back(r.true_normal);
        scan.faces.push_back(r.face);
        scan.beam_cells.push_back(beams.cells[b]);
      }
    }
    scan.counts.beams += counts.beams;
    scan.counts.returns += counts.returns;
    scan.counts.no_hit += counts.no_hit;
    scan.counts.out_of_range += counts.out_of_range;
    scan.counts.grazing += counts.grazing;
  }
  // One camera is an organised frame: its grid gives the disc model its
  // neighbours (surfel_estimation's pixel window), as a depth frame read from
  // a file does.
  if (camera && stations.size() == 1) {
    cloud.sensor = cloud.stations.front().frame;
    cloud.sensor.width = camera->width;
    cloud.sensor.height = camera->height;
    cloud.pixels = scan.beam_cells;
  }
  scan.trace_seconds = seconds_since(start);
  progress("scanning", 1.0);
  return scan;
}

}  // namespace occlusion
