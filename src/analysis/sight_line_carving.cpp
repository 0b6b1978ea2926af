#include "occlusion/analysis/sight_line_carving.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "occlusion/analysis/banded_discs.hpp"
#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/scan_tracer.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/banded_surfel_octree.hpp"
#include "occlusion/core/parallel.hpp"

namespace occlusion {

namespace {

// A line blocked by several discs frees one a pass (the nearest to the
// station). A noise-free scan's edges seldom stack more than a few; a real
// laser's coarse grid stacks more (each pass traces only the lines still
// blocked, so the later passes cost little).
constexpr int kMaxPasses = 32;
// The shrunk radius stops this share short of the crossing, so that the line
// passes beside the disc despite rounding.
constexpr float kBeside = 0.999f;
constexpr std::size_t kGrain = 2048;

// The radius that `shape` must have for `ray` to pass beside it: for a disc
// the distance of the crossing from its centre, for a sphere that of the
// ray's line.
float radius_beside(const Surfel& shape, const Ray& ray, float t_hit) {
  const Eigen::Vector3f crossing = ray.origin + t_hit * ray.direction;
  if (shape.oriented()) return kBeside * (crossing - shape.center).norm();
  const Eigen::Vector3f to_centre = shape.center - ray.origin;
  const Eigen::Vector3f along = ray.direction.normalized();
  return kBeside * (to_centre - to_centre.dot(along) * along).norm();
}

// A station whose own points the model hides by the kMaxBlockedShare is not
// carved: so many crossings say that it is not where those points were
// measured from (a wrong pose), or that its noise exceeds the bands, and
// carving would then cut the model apart. A station stored in its beams'
// order has shown where it stands relative to its own points (beam_order.hpp:
// its returns are equally spaced in angle from there), so the crossings of
// its own discs are the model's, which carving is for: a real laser's scan
// hides 15 to 20 % of itself before carving (3DTK's stations). Its pose
// among the other stations' scans is not shown that way (a pose moves a
// scan and its station together), so the crossings of their discs still
// count against it. Returns, per station, whether it is carved; its lines are
// dropped from `pending` (with their hits).
std::vector<bool> carved_stations(const PointCloud& cloud, const std::vector<Station>& stations,
                                  const BeamOrder& beams, std::vector<std::uint32_t>& pending,
                                  std::vector<std::optional<Hit>>& hits,
                                  SightLineCarving& carving) {
  std::vector<std::size_t> lines(stations.size(), 0), blocked(stations.size(), 0),
      by_others(stations.size(), 0);
  for (std::size_t k = 0; k < pending.size(); ++k) {
    const std::ptrdiff_t s = measuring_station(cloud, stations.size(), pending[k]);
    const auto st = static_cast<std::size_t>(s);
    ++lines[st];
    if (!hits[k]) continue;
    ++blocked[st];
    by_others[st] += measuring_station(cloud, stations.size(), hits[k]->primitive_id) != s;
  }
  std::vector<bool> carved(stations.size(), true);
  for (std::size_t s = 0; s < stations.size(); ++s) {
    const std::size_t counted = beams.in_beam_order(s) ? by_others[s] : blocked[s];
    if (static_cast<double>(counted) > kMaxBlockedShare * static_cast<double>(lines[s])) {
      carved[s] = false;
      const auto share = [&](std::size_t n) {
        return static_cast<double>(n) / static_cast<double>(lines[s]);
      };
      carving.implausible.push_back(
          {stations[s].name, share(blocked[s]), beams.in_beam_order(s), share(by_others[s])});
    }
  }
  if (carving.implausible.empty()) return carved;
  std::size_t kept = 0;
  for (std::size_t k = 0; k < pending.size(); ++k) {
    const auto s = static_cast<std::size_t>(measuring_station(cloud, stations.size(), pending[k]));
    if (!carved[s]) continue;
    pending[kept] = pending[k];
    hits[kept] = hits[k];
    ++kept;
  }
  pending.resize(kept);
  hits.resize(kept);
  return carved;
}

}  // namespace

SightLineCarving carve_sight_lines(const PointCloud& cloud, SurfelEstimate& estimate,
                                   unsigned threads, const Progress& progress) {
  SightLineCarving carving;
  if (estimate.thickness.size() != cloud.size()) return carving;
  const std::vector<Station> stations = scan_stations(cloud);
  if (stations.empty()) return carving;
  std::vector<std::uint32_t> pending;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (measuring_station(cloud, stations.size(), i) >= 0) {
      pending.push_back(static_cast<std::uint32_t>(i));
    }
  }
  carving.lines = pending.size();
  if (pending.empty()) return carving;

  progress("carving lines of sight", 0.0);
  const ScanOptions defaults;
  const double near_viewpoint = ScanTracer::disc_near_viewpoint(estimate);
  BandedSurfelOctree discs(banded_discs(estimate, threads), defaults.octree, progress);
  std::vector<std::uint8_t> shrunk(cloud.size(), 0);
  std::vector<Ray> rays;
  std::vector<std::optional<Hit>> hits;
  std::vector<bool> carved;  // per station, set by the first pass
  std::size_t uncarved_blocked = 0;
  const auto count_blocked = [&hits] {
    return static_cast<std::size_t>(
        std::count_if(hits.begin(), hits.end(), [](const auto& hit) { return hit.has_value(); }));
  };
  // Pass kMaxPasses only counts what is still blocked.
  for (int pass = 0; pass <= kMaxPasses && !pending.empty(); ++pass) {
    progress.check_cancel();
    rays.resize(pending.size());
    hits.assign(pending.size(), std::nullopt);
    parallel_for(pending.size(), kGrain, threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        const std::size_t i = pending[k];
        const std::ptrdiff_t station = measuring_station(cloud, stations.size(), i);
        rays[k] = scan_surfel_ray(stations[static_cast<std::size_t>(station)].frame.origin,
                                  estimate.surfels[i], estimate.thickness[i], near_viewpoint);
      }
    });
    static_assert(sizeof(PrimitiveId) == sizeof(std::uint32_t), "point indices are primitive ids");
    discs.intersect_batch(rays.data(), rays.size(), pending.data(), hits.data(), threads);
    if (pass == 0) {
      // Every station's blocked lines, the uncarved ones' too (which stay blocked).
      carving.blocked = count_blocked();
      carved = carved_stations(cloud, stations, estimate.beam_order, pending, hits, carving);
      uncarved_blocked = carving.blocked - count_blocked();
    }
    const std::size_t blocked = count_blocked();
    carving.still_blocked = uncarved_blocked + blocked;
    if (blocked == 0 || pass == kMaxPasses) break;
    // Each blocking shape takes the smallest radius any line asks of it; then
    // the blocked lines are traced again, and the lines to the shrunk points
    // (a point's reach along its own line follows its radius).
    std::vector<std::uint32_t> next;
    for (std::size_t k = 0; k < pending.size(); ++k) {
      if (!hits[k]) continue;
      next.push_back(pending[k]);
      const PrimitiveId j = hits[k]->primitive_id;
      BandedSurfel& shape = discs.shape_to_shrink(j);
      const float radius =
          std::min(shape.surfel.radius, radius_beside(shape.surfel, rays[k], hits[k]->t_hit));
      shape.surfel.radius = radius;
      estimate.surfels[j].radius = radius;
      if (!shrunk[j]) {
        shrunk[j] = 1;
        ++carving.shrunk;
        // Its own line, unless its station is left uncarved.
        const std::ptrdiff_t station = measuring_station(cloud, stations.size(), j);
        if (station >= 0 && carved[static_cast<std::size_t>(station)]) next.push_back(j);
      }
    }
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    pending.swap(next);
    progress("carving lines of sight", static_cast<double>(pass + 1) / kMaxPasses);
  }
  progress("carving lines of sight", 1.0);
  return carving;
}

}  // namespace occlusion
