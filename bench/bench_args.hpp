#pragma once
// Flag parsing shared by the bench tools: a value must be the whole argument,
// so "--threads 2x" is an error instead of silently meaning 2.

#include <charconv>
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
