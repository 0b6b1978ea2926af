#pragma once
// What every fuzz target shares: its input as a file (most readers take a
// path) and the rule that bad input may only ever be the error type the
// layer documents. Any other exception, a crash or a sanitizer report is a
// finding; libFuzzer stops at it and saves the input.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace occlusion::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A directory of this process's own, in RAM when /dev/shm exists; removed at exit.
inline const std::filesystem::path& scratch_directory() {
  static const std::filesystem::path directory = [] {
    std::error_code ignored;
    const std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ignored)
                                           ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path();
    std::filesystem::path made = base / ("occlusion_fuzz_" + std::to_string(::getpid()));
    std::filesystem::remove_all(made, ignored);
    std::filesystem::create_directories(made);
    std::atexit([] {
      std::error_code error;
      std::filesystem::remove_all(scratch_directory(), error);
    });
    return made;
  }();
  return directory;
}

// Writes `bytes` to scratch_directory()/name and returns its path.
inline std::string write_input(std::string_view bytes, const std::string& name) {
  const std::string path = (scratch_directory() / name).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path;
}

// Runs `body`; an exception of type Expected is a correctly reported bad
// input, anything else aborts (a finding).
template <class Expected, class Body>
void expect_only(Body&& body) {
  try {
    body();
  } catch (const Expected&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: unexpected exception: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz: unexpected non-standard exception\n");
    std::abort();
  }
}

}  // namespace occlusion::fuzz
