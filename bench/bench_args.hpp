#pragma once
// Flag parsing shared by the bench tools: a value must be the whole argument,
// so "--threads 2x" is an error instead of silently meaning 2.

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

namespace occlusion::bench {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The value after argv[i] (advancing i), or UsageError if the flag is last.
inline std::string flag_value(int argc, char** argv, int& i) {
  if (i + 1 >= argc) throw UsageError(std::string(argv[i]) + " needs a value");
  return argv[++i];
}

inline std::uint64_t parse_unsigned(const std::string& flag, const std::string& text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end) {
    throw UsageError(flag + " expects a non-negative integer, got '" + text + "'");
  }
  return value;
}

// A thread count, capped at 1024 like the CLI's --threads.
inline unsigned parse_threads(const std::string& flag, const std::string& text) {
  const std::uint64_t threads = parse_unsigned(flag, text);
  return static_cast<unsigned>(threads < 1024 ? threads : 1024);
}

// The flags of the benches that trace a sampled room's points (bench_poc,
// bench_discs).
struct PointBenchOptions {
  std::size_t points = 1'000'000;
  std::size_t triangles = 100'000;
  std::size_t rays_per_vp = 30'000;
  std::size_t num_vp = 9;  // -poc's grid viewpoints
  unsigned threads = 2;
  std::uint64_t seed = 1;
  int repeat = 3;
};

// Parses argv[i] (advancing i past its value) into `o` if it is one of the
// flags above; returns false for any other argument.
inline bool parse_point_bench_flag(PointBenchOptions& o, int argc, char** argv, int& i) {
  const std::string arg = argv[i];
  if (arg == "--points") {
    o.points = parse_unsigned(arg, flag_value(argc, argv, i));
  } else if (arg == "--triangles") {
    o.triangles = parse_unsigned(arg, flag_value(argc, argv, i));
  } else if (arg == "--rays-per-vp") {
    o.rays_per_vp = parse_unsigned(arg, flag_value(argc, argv, i));
  } else if (arg == "--num-vp") {
    o.num_vp = parse_unsigned(arg, flag_value(argc, argv, i));
  } else if (arg == "--threads") {
    o.threads = parse_threads(arg, flag_value(argc, argv, i));
  } else if (arg == "--seed") {
    o.seed = parse_unsigned(arg, flag_value(argc, argv, i));
  } else if (arg == "--repeat") {
    o.repeat = static_cast<int>(
        std::min<std::uint64_t>(1000, parse_unsigned(arg, flag_value(argc, argv, i))));
  } else {
    return false;
  }
  return true;
}

// UsageError for counts of 0 or more than 100M points.
inline void check_point_bench_options(const PointBenchOptions& o) {
  if (o.points == 0 || o.triangles == 0 || o.rays_per_vp == 0 || o.num_vp == 0 || o.threads == 0 ||
      o.repeat == 0) {
    throw UsageError(
        "--points, --triangles, --rays-per-vp, --num-vp, --threads and --repeat must be > 0");
  }
  if (o.points > 100'000'000) throw UsageError("--points must be at most 100000000");
}

// A bench tool's main: run(parse(argc, argv)), whose result is the exit
// status; a UsageError prints it with the usage and exits 2, anything else
// thrown prints it and exits 1.
template <class Parse, class Run>
int run_tool(const char* name, const char* usage, int argc, char** argv, const Parse& parse,
             const Run& run) {
  try {
    return run(parse(argc, argv));
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s\n%s", name, e.what(), usage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
}

}  // namespace occlusion::bench
