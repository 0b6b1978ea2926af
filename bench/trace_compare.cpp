#include "trace_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bench_common.hpp"

namespace occlusion::bench {

double percent(std::size_t k, std::size_t n) {
  return n > 0 ? 100.0 * static_cast<double>(k) / static_cast<double>(n) : 100.0;
}

void print_trace_header() {
  std::printf("%-48s %10s %10s %12s %10s\n", "", "build (s)", "trace (s)", "rays/s", "hit");
}

void print_trace_row(const std::string& what, double build, double trace, std::size_t rays,
                     double hit_percent) {
  std::printf("%-48s %10.4f %10.4f %10.2f M %9.3f%%\n", what.c_str(), build, trace,
              static_cast<double>(rays) / trace / 1e6, hit_percent);
}

void print_ratio(const char* what, const Samples& ours, const Samples& theirs, std::size_t rays) {
  const auto side = [rays](const char* who, const Samples& samples) {
    std::printf("%s %.4f / %.4f s", who, samples.min(), samples.median());
    if (rays > 0) std::printf(" (%.2f M rays/s)", static_cast<double>(rays) / samples.min() / 1e6);
  };
  std::printf("%-6s ", what);
  side("ours", ours);
  side(", embree", theirs);
  std::printf(" [min / median of %zu]; ours/embree %.2f (min), %.2f (median)\n",
              ours.seconds.size(), theirs.min() / ours.min(), theirs.median() / ours.median());
}

HitAgreement compare_hits(const std::optional<Hit>* ours, const std::optional<Hit>* theirs,
                          std::size_t count, double t_tolerance) {
  HitAgreement a;
  a.rays = count;
  for (std::size_t i = 0; i < count; ++i) {
    const bool o = ours[i].has_value(), t = theirs[i].has_value();
    a.ours += o;
    a.theirs += t;
    if (o != t) {
      a.only_ours += o;
      a.only_theirs += t;
      a.disagreeing.push_back(i);
    }
    if (!o || !t) continue;
    ++a.both;
    const double x = ours[i]->t_hit, y = theirs[i]->t_hit;
    const double relative = std::abs(x - y) / std::max({std::abs(x), std::abs(y), 1e-30});
    a.worst_t = std::max(a.worst_t, relative);
    a.same_t += relative <= t_tolerance;
    a.same_point += ours[i]->primitive_id == theirs[i]->primitive_id;
  }
  return a;
}

void print_hit_agreement(const char* label, const HitAgreement& a, double t_tolerance) {
  std::printf(
      "%-8s hit/miss agree on %.4f%% of rays (%zu hit only for us, %zu only for Embree); of "
      "%s common hits, t within %g relative on %.4f%% (largest difference %.2g), same point on "
      "%.4f%%\n",
      label, percent(a.rays - a.only_ours - a.only_theirs, a.rays), a.only_ours, a.only_theirs,
      grouped(a.both).c_str(), t_tolerance, percent(a.same_t, a.both), a.worst_t,
      percent(a.same_point, a.both));
}

FlagAgreement compare_flags(const std::uint8_t* ours, const std::uint8_t* theirs,
                            std::size_t count) {
  FlagAgreement a;
  a.rays = count;
  for (std::size_t i = 0; i < count; ++i) {
    a.ours += ours[i] != 0;
    a.theirs += theirs[i] != 0;
    if ((ours[i] != 0) == (theirs[i] != 0)) continue;
    a.only_ours += ours[i] != 0;
    a.only_theirs += theirs[i] != 0;
    a.disagreeing.push_back(i);
  }
  return a;
}

void print_flag_agreement(const char* label, const FlagAgreement& a) {
  std::printf("%-8s flags agree on %.4f%% of rays: %zu blocked only for us, %zu only for Embree\n",
              label, percent(a.rays - a.only_ours - a.only_theirs, a.rays), a.only_ours,
              a.only_theirs);
}

}  // namespace occlusion::bench
