#pragma once
// What the point benches (bench_poc: spheres, bench_discs: surfels) print the
// same way: the table of build and trace times, and how far our tracer and
// Embree agree on the same rays.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/core/hit.hpp"

namespace occlusion::bench {

// 100 k / n, or 100 when n is 0.
double percent(std::size_t k, std::size_t n);

// The header of the rows below.
void print_trace_header();
// One row: what, build and trace seconds, rays/s, share of rays that hit.
void print_trace_row(const std::string& what, double build, double trace, std::size_t rays,
                     double hit_percent);

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
