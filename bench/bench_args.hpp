#pragma once
// Flag parsing shared by the bench tools: a value must be the whole argument,
// so "--threads 2x" is an error instead of silently meaning 2.

#include <charconv>
#include <cstdint>
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

}  // namespace occlusion::bench
