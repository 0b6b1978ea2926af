#include "occlusion/app/memory_budget.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include <unistd.h>

#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

namespace {

constexpr std::uint64_t kMegabyte = std::uint64_t{1} << 20;
constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();

// a * b, saturating: the estimate of an absurd request must not wrap to a small one.
std::uint64_t times(std::uint64_t a, std::uint64_t b) {
  return (b != 0 && a > kMax / b) ? kMax : a * b;
}

std::uint64_t plus(std::uint64_t a, std::uint64_t b) {
  return a > kMax - b ? kMax : a + b;
}

std::string count(std::uint64_t n) {
  std::string digits = std::to_string(n);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) {
    digits.insert(static_cast<std::size_t>(at), ",");
  }
  return digits;
}

// A saturated count is a bound, not a count.
std::string at_least(std::uint64_t n) {
  return n == kMax ? "more than " + count(n) : count(n);
}

std::string megabytes(std::uint64_t bytes) {
  char text[64];
  std::snprintf(text, sizeof text, "%.0f MB", static_cast<double>(bytes) / kMegabyte);
  return text;
}

// Per element of the octrees: the primitive and its share of the nodes.
constexpr std::uint64_t kTriangleOctreeBytes = 128;
constexpr std::uint64_t kSphereOctreeBytes = 64;
// The disc model beside it (surfel_estimation.hpp): the surfels and their
// thickness, the estimate's per-point arrays and kd-tree, and the octree's
// larger primitive.
constexpr std::uint64_t kDiscModelBytes = 96;

}  // namespace

std::uint64_t machine_memory_mb() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0;
  return times(static_cast<std::uint64_t>(pages), static_cast<std::uint64_t>(page_size)) /
         kMegabyte;
}

void check_memory_budget(const MemoryEstimate& estimate, std::uint64_t max_memory_mb) {
  const std::string needs = std::string("this work needs ") +
                            (estimate.bytes == kMax ? "more than " : "about ") +
                            megabytes(estimate.bytes) + " (" + estimate.made_of + "), ";
  const std::string ask = estimate.lower.empty() ? "ask for less" : "lower " + estimate.lower;
  if (max_memory_mb == 0) {
    // No budget still cannot mean more than the machine has: such work would
    // end in an allocation failure (or the kernel's OOM killer) after its
    // other stages had run.
    const std::uint64_t machine = machine_memory_mb();
    if (machine == 0 || estimate.bytes <= times(machine, kMegabyte)) return;
    throw UsageError(needs + "more than this machine's memory (" + count(machine) + " MB): " + ask);
  }
  if (estimate.bytes <= times(max_memory_mb, kMegabyte)) return;
  throw UsageError(needs + "more than max_memory_mb = " + count(max_memory_mb) + ": " + ask +
                   ", or raise max_memory_mb where the machine has the memory");
}

MemoryEstimate mesh_occlusion_memory(const TriangleMesh& mesh, double samples_per_unit_area,
                                     std::size_t viewpoints) {
  const std::uint64_t samples = total_samples(mesh, samples_per_unit_area);
  // Per sample: its point (24 bytes) and face (4), and one byte per viewpoint.
  std::uint64_t bytes = times(samples, 28 + static_cast<std::uint64_t>(viewpoints));
  bytes = plus(bytes, times(mesh.face_count(), kTriangleOctreeBytes));
  return {bytes, at_least(samples) + " samples x " + count(viewpoints) + " viewpoints",
          "samples_per_unit_area"};
}

MemoryEstimate cloud_occlusion_memory(std::size_t points, std::size_t viewpoints,
                                      std::uint64_t rays_per_viewpoint, bool keep_escapes,
                                      bool discs) {
  std::uint64_t bytes = times(points, kSphereOctreeBytes + (discs ? kDiscModelBytes : 0));
  std::string made_of = count(points) + (discs ? " points as discs" : " points");
  if (keep_escapes) {
    // Every ray may escape: 12 bytes of direction each.
    bytes = plus(bytes, times(times(rays_per_viewpoint, viewpoints), 12));
    made_of += ", " + count(rays_per_viewpoint) + " rays x " + count(viewpoints) +
               " viewpoints of escape directions";
  }
  return {bytes, made_of, keep_escapes ? "num_rays_per_vp" : ""};
}

MemoryEstimate scan_memory(std::size_t points, std::size_t viewpoints, bool discs) {
  // The octree, the counts and first stations, the points' Morton order, and
  // the written subset (a copy of the cloud at most; the order's sort needs
  // less, before); per viewpoint only its few counters.
  const std::uint64_t bytes =
      times(points, kSphereOctreeBytes + 4 + 4 + 4 + 32 + (discs ? kDiscModelBytes : 0));
  return {bytes,
          count(points) + (discs ? " points as discs, " : " points, ") + count(viewpoints) +
              " viewpoints",
          ""};
}

MemoryEstimate simulate_memory(const TriangleMesh& mesh, std::uint64_t beams_per_station,
                               std::size_t stations, bool truth) {
  // Per beam at most one point: position, label, instance, station, the
  // truth kept beside it (point, normal, face, cell: 36 bytes), and a written
  // copy; the rays and hits of one block are small beside it.
  const std::uint64_t beams = times(beams_per_station, stations);
  std::uint64_t bytes = times(beams, 24 + 36 + 24 + (truth ? 28 : 0));
  bytes = plus(bytes, times(mesh.face_count(), kTriangleOctreeBytes + 48));
  return {bytes,
          at_least(beams) + " beams (" + at_least(beams_per_station) + " a station x " +
              count(stations) + " stations)",
          "azimuth_step and elevation_step, or width and height"};
}

MemoryEstimate plan_memory(MemoryEstimate model, std::uint64_t targets, std::size_t candidates,
                           bool intervisible) {
  // Per target beside the model: its weight three times (the job's, the
  // visibility's, the matrix's), the visibility's index and copy of what its
  // ray reads (a disc or a sample and its face), its position in float while
  // they are put in Morton order, a mesh sample's position in the report.
  // 7,974,200 samples of sample_room.obj peaked at 910 MB, estimated 954.
  constexpr std::uint64_t kPlanTargetBytes = 3 * 8 + 4 + 32 + 12 + 24;
  model.bytes = plus(model.bytes, times(targets, kPlanTargetBytes));
  // One bit per (candidate, target), each row padded to whole 64-bit words.
  const std::uint64_t row_bytes = times(targets / 64 + (targets % 64 != 0 ? 1 : 0), 8);
  model.bytes = plus(model.bytes, times(candidates, row_bytes));
  // The model's own words name viewpoints, which plan has not.
  model.made_of = at_least(targets) + " targets with their model, and the coverage matrix of " +
                  count(candidates) + " candidates x " + at_least(targets) + " targets";
  if (intervisible) {
    // A byte per pair of candidates.
    model.bytes = plus(model.bytes, times(candidates, candidates));
    model.made_of += ", and " + count(candidates) + " x " + count(candidates) +
                     " pairs of candidates (intervisible)";
  }
  model.lower = (model.lower.empty() ? "" : model.lower + ", or ") +
                "the candidates (a larger spacing, a shorter candidates file" +
                (intervisible ? ", no intervisible" : "") + ")";
  return model;
}

MemoryEstimate region_growing_memory(std::size_t points, const RegionGrowingOptions& options) {
  // PCL's point (16 bytes), normal (32), kd-tree (~40), label and cluster ids.
  std::uint64_t bytes = times(points, 100);
  // Region growing keeps every point's neighbour list.
  bytes = plus(bytes, times(times(points, options.neighbours), 4));
  // Normal estimation: each thread holds k neighbours (index and distance);
  // the search gives at most every point.
  const std::uint64_t k = std::min<std::uint64_t>(options.normal_k, points);
  bytes = plus(bytes, times(times(resolve_thread_count(options.threads), k), 8));
  return {bytes,
          count(points) + " points, " + count(options.neighbours) + " neighbours each, normal_k " +
              count(options.normal_k),
          "neighbours"};
}

}  // namespace occlusion
