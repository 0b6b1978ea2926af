#pragma once
// What the point benches (bench_poc: spheres, bench_discs: surfels) print the
// same way: the table of build and trace times, and how far our tracer and
// Embree agree on the same rays.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "bench_common.hpp"
#include "cloud_replay.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion::bench {

// 100 k / n, or 100 when n is 0.
double percent(std::size_t k, std::size_t n);

// Our octree's and Embree's results and times on the same -poc rays (closest
// hit) and -fscan rays (any hit, ours ignoring the target).
struct PointTraces {
  Samples our_poc, embree_poc, our_scan, embree_scan;
  std::vector<std::optional<Hit>> our_hits, their_hits;
  std::vector<std::uint8_t> our_blocked, their_blocked;
};

// Traces both sets of rays `repetitions` times with each tracer (an Octree,
// and EmbreePoints or EmbreeDiscs), ours and Embree's in turn.
template <class Tree, class Embree>
PointTraces trace_both(const Tree& tree, const Embree& embree, const std::vector<Ray>& poc_rays,
                       const ScanRays& scan_rays, unsigned threads, int repetitions) {
  PointTraces r;
  const std::size_t np = poc_rays.size(), ns = scan_rays.rays.size();
  r.our_hits.resize(np);
  r.their_hits.resize(np);
  std::tie(r.our_poc, r.embree_poc) = alternating_samples(
      repetitions,
      [&] {
        return timed([&] {
          tree.intersect_batch(poc_rays.data(), np, nullptr, r.our_hits.data(), threads);
        });
      },
      [&] {
        return timed([&] { embree.intersect(poc_rays.data(), np, r.their_hits.data(), threads); });
      });
  r.our_blocked.resize(ns);
  r.their_blocked.resize(ns);
  std::tie(r.our_scan, r.embree_scan) = alternating_samples(
      repetitions,
      [&] {
        return timed([&] {
          tree.occluded_batch(scan_rays.rays.data(), ns, scan_rays.ignore.data(),
                              r.our_blocked.data(), threads, BatchOrder::kAsGiven);
        });
      },
      [&] {
        return timed(
            [&] { embree.occluded(scan_rays.rays.data(), ns, r.their_blocked.data(), threads); });
      });
  return r;
}

// The header of the rows below.
void print_trace_header();
// One row: what, build and trace seconds, rays/s, share of rays that hit.
void print_trace_row(const std::string& what, double build, double trace, std::size_t rays,
                     double hit_percent);

// "WHAT ours MIN / MEDIAN s (R M rays/s), embree ... [min / median of N];
// ours/embree MIN-RATIO (min), MEDIAN-RATIO (median)", the ratio being Embree's
// time over ours; no rays/s when rays is 0.
void print_ratio(const char* what, const Samples& ours, const Samples& theirs, std::size_t rays);

// Closest hits of the same rays by two tracers.
struct HitAgreement {
  std::size_t rays = 0, ours = 0, theirs = 0;  // rays, and those each tracer hit
  std::size_t only_ours = 0, only_theirs = 0;  // hit by one tracer only
  std::size_t both = 0, same_t = 0, same_point = 0;
  double worst_t = 0.0;                  // largest relative difference of t on common hits
  std::vector<std::size_t> disagreeing;  // the rays hit by one tracer only
};
HitAgreement compare_hits(const std::optional<Hit>* ours, const std::optional<Hit>* theirs,
                          std::size_t count, double t_tolerance);
// "LABEL hit/miss agree on ...% of rays (...); of N common hits, t within ...".
void print_hit_agreement(const char* label, const HitAgreement& agreement, double t_tolerance);

// Any-hit flags of the same rays by two tracers.
struct FlagAgreement {
  std::size_t rays = 0, ours = 0, theirs = 0, only_ours = 0, only_theirs = 0;
  std::vector<std::size_t> disagreeing;
};
FlagAgreement compare_flags(const std::uint8_t* ours, const std::uint8_t* theirs,
                            std::size_t count);
// "LABEL flags agree on ...% of rays: N blocked only for us, M only for Embree".
void print_flag_agreement(const char* label, const FlagAgreement& agreement);

}  // namespace occlusion::bench
