#include "occlusion/analysis/virtual_scanner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "analysis_support.hpp"
#include "occlusion/analysis/beam_tiles.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/normal_deviates.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

namespace {

using analysis_support::Clock;
using analysis_support::seconds_since;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
// A band of strips is traced before its returns join the cloud: at most
// this many beams (bounds the returns held, 44 bytes a beam) and rays (how
// long a cancel waits), but at least one strip.
constexpr std::size_t kBeamsPerBand = std::size_t{1} << 19;
constexpr std::size_t kRaysPerBand = std::size_t{1} << 20;
// Beams one thread aims, traces and turns into returns at a time, in whole
// tiles, so that each of the octree's packets is a tile.
constexpr std::size_t kBeamsPerBatch = 1024;

// One sub-ray of a divergent beam: its offset in the footprint, as a fraction
// of the half divergence, and the tangent of its angle over that fraction.
struct SubRay {
  Eigen::Vector2d offset;
  double scale = 0.0;  // 0 for the beam's centre
};

// The beam's sub-rays: the centre, then a sunflower spiral that fills the disc evenly.
std::vector<SubRay> footprint(unsigned samples, double half_angle) {
  std::vector<SubRay> subs{SubRay{Eigen::Vector2d::Zero(), 0.0}};
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (unsigned k = 1; k < samples; ++k) {
    const double radius = std::sqrt(static_cast<double>(k) / static_cast<double>(samples - 1));
    const double angle = golden * static_cast<double>(k);
    const Eigen::Vector2d offset(radius * std::cos(angle), radius * std::sin(angle));
    subs.push_back(SubRay{offset, std::tan(half_angle * offset.norm()) / offset.norm()});
  }
  return subs;
}

// What became of a beam.
enum class Outcome : std::uint8_t { kNoHit, kPoint, kOutOfRange, kGrazing };

struct Return {
  Eigen::Vector3f position, true_point, true_normal;
  std::uint32_t face = 0;
  Outcome outcome = Outcome::kNoHit;
};

// The face's unit normal, turned to face the ray.
Eigen::Vector3f facing_normal(const PackedTriangle& tri, const Eigen::Vector3f& direction) {
  Eigen::Vector3f n = tri.normal / tri.normal_length;
  return n.dot(direction) > 0.0f ? Eigen::Vector3f(-n) : n;
}

// The laser's beam angles, once for every station: a full dome at 0.1
// degrees is 5.4 M beams over 3,600 columns and 1,501 rows.
struct LaserAngles {
  std::vector<double> cos_azimuth, sin_azimuth, cos_elevation, sin_elevation;

  explicit LaserAngles(const LaserScannerModel& laser) {
    for (std::size_t column = 0; column < laser.columns(); ++column) {
      cos_azimuth.push_back(std::cos(laser.azimuth_deg(column) * kDegree));
      sin_azimuth.push_back(std::sin(laser.azimuth_deg(column) * kDegree));
    }
    for (std::size_t row = 0; row < laser.rows(); ++row) {
      cos_elevation.push_back(std::cos(laser.elevation_deg(row) * kDegree));
      sin_elevation.push_back(std::sin(laser.elevation_deg(row) * kDegree));
    }
  }
};

// One station's beams as the threads aim, trace and turn them into returns.
struct StationScan {
  const TriangleOctree& octree;
  const LaserScannerModel* laser;  // one of the two
  const DepthCameraModel* camera;
  const LaserAngles* angles;  // the laser's
  const std::vector<SubRay>& subs;
  const SimulationOptions& options;
  BeamTiles tiles;
  Eigen::Vector3d origin;
  Eigen::Matrix3d rotation;
  std::size_t station = 0;
  double cos_limit = 0.0;  // of the incidence limit

  // The beam's central unit direction (laser) or its pixel ray with z = 1 in
  // the camera frame (camera: t is then the depth), in the mesh's frame.
  Eigen::Vector3d direction(std::size_t row, std::size_t column) const {
    Eigen::Vector3d local;
    if (laser) {
      local = {angles->cos_elevation[row] * angles->cos_azimuth[column],
               angles->cos_elevation[row] * angles->sin_azimuth[column],
               angles->sin_elevation[row]};
    } else {
      local = {(static_cast<double>(column) - camera->principal_x()) / camera->fx,
               (static_cast<double>(row) - camera->principal_y()) / camera->fy, 1.0};
    }
    return rotation * local;
  }

  // The beam's rays (subs.size() of them for the laser, one for the camera).
  void aim(const Eigen::Vector3d& d, Ray* rays) const {
    const Eigen::Vector3f origin_f = origin.cast<float>();
    if (camera) {
      rays[0].origin = origin_f;
      rays[0].direction = d.cast<float>();  // z = 1 in the camera: t is depth
      rays[0].t_min = 0.0f;
      rays[0].t_max = static_cast<float>(camera->max_depth);
      return;
    }
    Eigen::Vector3d u = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
    if (subs.size() > 1) {
      u = d.unitOrthogonal();
      v = d.cross(u);
    }
    for (std::size_t s = 0; s < subs.size(); ++s) {
      Eigen::Vector3d dir = d;
      if (subs[s].scale > 0.0) {
        dir += subs[s].scale * (subs[s].offset.x() * u + subs[s].offset.y() * v);
      }
      dir.normalize();
      rays[s].origin = origin_f;
      rays[s].direction = dir.cast<float>();
      rays[s].t_min = 0.0f;
      rays[s].t_max = static_cast<float>(laser->max_range);
    }
  }

  // The beam's measured range with noise drawn from its own stream (seed,
  // station, cell), so that it does not depend on which thread draws it.
  double with_noise(double value, double sigma, std::size_t cell) const {
    if (!options.noise) return value;
    NormalDeviates noise(options.seed, (static_cast<std::uint64_t>(station) << 40) ^ cell);
    return value + sigma * noise.next();
  }

  Return laser_return(const Ray* rays, const std::optional<Hit>* hits, const Eigen::Vector3d& d,
                      std::size_t cell) const;
  Return camera_return(const Ray& ray, const std::optional<Hit>& hit, const Eigen::Vector3d& d,
                       std::size_t cell) const;
};

// The first echo, and the echoes a pulse could not tell from it.
Return StationScan::laser_return(const Ray* rays, const std::optional<Hit>* hits,
                                 const Eigen::Vector3d& d, std::size_t cell) const {
  Return r;
  const std::size_t count = subs.size();
  std::size_t nearest = count;
  for (std::size_t s = 0; s < count; ++s) {
    if (hits[s] && (nearest == count || hits[s]->t_hit < hits[nearest]->t_hit)) nearest = s;
  }
  if (nearest == count) return r;  // no hit
  const Hit& first = *hits[nearest];
  double range_sum = 0.0;
  std::size_t merged = 0;
  for (std::size_t s = 0; s < count; ++s) {
    if (hits[s] && hits[s]->t_hit <= first.t_hit + laser->echo_window) {
      range_sum += hits[s]->t_hit;
      ++merged;
    }
  }
  const double range = range_sum / static_cast<double>(merged);
  const Ray& ray = rays[nearest];
  const Eigen::Vector3f normal = facing_normal(octree.shape(first.primitive_id), ray.direction);
  if (-normal.dot(ray.direction) < cos_limit) {
    r.outcome = Outcome::kGrazing;
    return r;
  }
  if (range < laser->min_range) {
    r.outcome = Outcome::kOutOfRange;
    return r;
  }
  const double measured = with_noise(range, laser->range_sigma(range), cell);
  r.outcome = Outcome::kPoint;
  r.position = (origin + measured * d).cast<float>();
  r.true_point = ray.at(first.t_hit);
  r.true_normal = normal;
  r.face = first.primitive_id;
  return r;
}

Return StationScan::camera_return(const Ray& ray, const std::optional<Hit>& hit,
                                  const Eigen::Vector3d& d, std::size_t cell) const {
  Return r;
  if (!hit) return r;
  const double depth = hit->t_hit;
  const Eigen::Vector3f unit = ray.direction.normalized();
  const Eigen::Vector3f normal = facing_normal(octree.shape(hit->primitive_id), unit);
  if (-normal.dot(unit) < cos_limit) {
    r.outcome = Outcome::kGrazing;
    return r;
  }
  double measured = depth;
  if (options.noise) {
    measured = camera->quantised_depth(with_noise(depth, camera->depth_sigma(depth), cell));
  }
  if (depth < camera->min_depth || measured < camera->min_depth || measured > camera->max_depth) {
    r.outcome = Outcome::kOutOfRange;
    return r;
  }
  r.outcome = Outcome::kPoint;
  r.position = (origin + measured * d).cast<float>();
  r.true_point = ray.at(hit->t_hit);
  r.true_normal = normal;
  r.face = hit->primitive_id;
  return r;
}

// Traces one strip's beams in tile order, about kBeamsPerBatch at a time on
// this thread, into returns[cell - first_cell] of the band starting at
// first_cell, and counts what became of them.
BeamCounts scan_strip(const StationScan& scan, std::size_t strip, std::size_t first_cell,
                      Return* returns) {
  BeamCounts counts;  // here, not in a vector other threads write beside it
  const std::size_t subs = scan.camera ? 1 : scan.subs.size();
  const std::size_t tile_beams =
      BeamTiles::kColumns * std::min(BeamTiles::kRows, scan.tiles.rows - strip * BeamTiles::kRows);
  const std::size_t tiles_per_batch = std::max<std::size_t>(1, kBeamsPerBatch / tile_beams);
  std::vector<Ray> rays(tiles_per_batch * tile_beams * subs);
  std::vector<std::optional<Hit>> hits(rays.size());
  std::vector<Eigen::Vector3d> directions(tiles_per_batch * tile_beams);
  std::vector<std::uint32_t> cells(directions.size());
  const std::size_t tiles = scan.tiles.tiles_per_strip();
  for (std::size_t first = 0; first < tiles; first += tiles_per_batch) {
    std::size_t n = 0;
    scan.tiles.visit(strip, first, std::min(tiles, first + tiles_per_batch),
                     [&](std::size_t row, std::size_t column) {
                       cells[n] = static_cast<std::uint32_t>(row * scan.tiles.columns + column);
                       directions[n] = scan.direction(row, column);
                       scan.aim(directions[n], &rays[n * subs]);
                       ++n;
                     });
    scan.octree.intersect_batch(rays.data(), n * subs, nullptr, hits.data(), 1,
                                BatchOrder::kAsGiven);
    for (std::size_t b = 0; b < n; ++b) {
      Return& r = returns[cells[b] - first_cell];
      r = scan.camera
              ? scan.camera_return(rays[b], hits[b], directions[b], cells[b])
              : scan.laser_return(&rays[b * subs], &hits[b * subs], directions[b], cells[b]);
      ++counts.beams;
      counts.returns += r.outcome == Outcome::kPoint;
      counts.no_hit += r.outcome == Outcome::kNoHit;
      counts.out_of_range += r.outcome == Outcome::kOutOfRange;
      counts.grazing += r.outcome == Outcome::kGrazing;
    }
  }
  return counts;
}

void add_counts(BeamCounts& total, const BeamCounts& part) {
  total.beams += part.beams;
  total.returns += part.returns;
  total.no_hit += part.no_hit;
  total.out_of_range += part.out_of_range;
  total.grazing += part.grazing;
}

// As PointCloud::reserve_positions does for positions.
template <class T>
void reserve_huge_pages(std::vector<T>& values, std::size_t count) {
  values.reserve(count);
  advise_huge_pages(values.data(), values.capacity() * sizeof(T));
}

// The scan's per-point arrays, each grown to hold `count` points without
// moving again: a station's worth at a time, offered huge pages (the cloud
// of a 0.1 degree station is 5 M points, 280 MB, which 4 KiB pages fault in
// 70,000 times).
void reserve_points(SimulatedScan& scan, std::size_t count) {
  PointCloud& cloud = scan.cloud;
  if (count <= cloud.positions.capacity()) return;
  count = std::max(count, 2 * cloud.positions.capacity());  // many stations: linear, not quadratic
  reserve_huge_pages(cloud.positions, count);
  reserve_huge_pages(cloud.labels, count);
  reserve_huge_pages(cloud.instances, count);
  reserve_huge_pages(cloud.station_ids, count);
  reserve_huge_pages(scan.true_points, count);
  reserve_huge_pages(scan.true_normals, count);
  reserve_huge_pages(scan.faces, count);
  reserve_huge_pages(scan.beam_cells, count);
}

// Appends the band's points to the scan in cell order: each strip's points
// (counts[k].returns of strip first_strip + k) copied at its own offset, the
// strips in parallel.
void append_band(SimulatedScan& scan, const StationScan& station, std::size_t first_strip,
                 const std::vector<BeamCounts>& counts, const Return* returns,
                 const TriangleMesh& mesh, const std::vector<std::int32_t>& group_label) {
  std::vector<std::size_t> offset(counts.size() + 1, scan.cloud.positions.size());
  for (std::size_t k = 0; k < counts.size(); ++k) offset[k + 1] = offset[k] + counts[k].returns;
  const std::size_t size = offset.back();
  PointCloud& cloud = scan.cloud;
  cloud.positions.resize(size);
  cloud.labels.resize(size);
  cloud.instances.resize(size);
  cloud.station_ids.resize(size);
  scan.true_points.resize(size);
  scan.true_normals.resize(size);
  scan.faces.resize(size);
  scan.beam_cells.resize(size);
  const std::size_t band_first = station.tiles.first_cell(first_strip);
  const auto station_id = static_cast<std::int32_t>(station.station);
  parallel_for(counts.size(), 1, station.options.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      std::size_t out = offset[k];
      const std::size_t last = station.tiles.first_cell(first_strip + k + 1);
      for (std::size_t cell = station.tiles.first_cell(first_strip + k); cell < last; ++cell) {
        const Return& r = returns[cell - band_first];
        if (r.outcome != Outcome::kPoint) continue;
        const std::uint32_t group = mesh.face_group[r.face];
        cloud.positions[out] = r.position;
        cloud.labels[out] = group_label[group];
        cloud.instances[out] = static_cast<std::int32_t>(group);
        cloud.station_ids[out] = station_id;
        scan.true_points[out] = r.true_point;
        scan.true_normals[out] = r.true_normal;
        scan.faces[out] = r.face;
        scan.beam_cells[out] = static_cast<std::uint32_t>(cell);
        ++out;
      }
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
  const TriangleOctree octree(pack_triangles(mesh, cloud.shift), OctreeOptions{}, progress);
  scan.build_seconds = seconds_since(start);

  // Classes and instances from the groups.
  std::vector<std::int32_t> group_label(mesh.group_names.size());
  std::unordered_map<std::string, std::int32_t> class_ids;
  for (std::size_t g = 0; g < mesh.group_names.size(); ++g) {
    const std::string name = class_of_group(mesh.group_names[g]);
    const auto found = class_ids.emplace(name, static_cast<std::int32_t>(cloud.class_names.size()));
    if (found.second) cloud.class_names.push_back(name);
    group_label[g] = found.first->second;
  }

  const std::vector<SubRay> subs =
      laser != nullptr && laser->beam_divergence_mrad > 0.0
          ? footprint(laser->beam_samples, 0.5e-3 * laser->beam_divergence_mrad)
          : footprint(1, 0.0);
  const BeamTiles tiles{laser ? laser->columns() : camera->width,
                        laser ? laser->rows() : camera->height};
  const std::size_t cells = tiles.columns * tiles.rows;
  if (cells > std::size_t{1} << 32) {
    throw std::invalid_argument("virtual scanner: more than 2^32 beams a station");
  }
  const std::optional<LaserAngles> angles =
      laser ? std::optional<LaserAngles>(*laser) : std::nullopt;
  const std::size_t strip_beams = BeamTiles::kRows * tiles.columns;
  const std::size_t strips_per_band = std::max<std::size_t>(
      1, std::min(kBeamsPerBand / strip_beams, kRaysPerBand / (strip_beams * subs.size())));
  LargeVector<Return> returns(std::min(cells, strips_per_band * strip_beams));
  const double cos_limit = std::cos(options.max_incidence_deg * kDegree);

  start = Clock::now();
  scan.per_station.resize(stations.size());
  for (std::size_t s = 0; s < stations.size(); ++s) {
    const ScannerStation& station = stations[s];
    const StationScan station_scan{octree,
                                   laser,
                                   camera,
                                   angles ? &*angles : nullptr,
                                   subs,
                                   options,
                                   tiles,
                                   station.position - cloud.shift,
                                   station.orientation.normalized().toRotationMatrix(),
                                   s,
                                   cos_limit};
    Station recorded;
    recorded.name = station.name;
    recorded.frame.origin = station_scan.origin;
    recorded.frame.orientation = station.orientation.normalized();
    if (laser) {
      recorded.frame.width = tiles.columns;
      recorded.frame.height = tiles.rows;
    }
    cloud.stations.push_back(recorded);
    reserve_points(scan, cloud.size() + cells);

    BeamCounts& counts = scan.per_station[s];
    for (std::size_t first = 0; first < tiles.strips(); first += strips_per_band) {
      progress.check_cancel();
      progress("scanning", (static_cast<double>(s) +
                            static_cast<double>(first) / static_cast<double>(tiles.strips())) /
                               static_cast<double>(stations.size()));
      const std::size_t last = std::min(tiles.strips(), first + strips_per_band);
      std::vector<BeamCounts> strip_counts(last - first);
      const std::size_t band_first = tiles.first_cell(first);
      parallel_for(last - first, 1, options.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
          strip_counts[k] = scan_strip(station_scan, first + k, band_first, returns.data());
        }
      });
      append_band(scan, station_scan, first, strip_counts, returns.data(), mesh, group_label);
      for (const BeamCounts& strip : strip_counts) add_counts(counts, strip);
    }
    add_counts(scan.counts, counts);
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
