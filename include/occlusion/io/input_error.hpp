#pragma once
// The two failures io/ reports: bad input (the CLI exits with code 3) and a
// failure writing an output. Both name the file, so the user knows where to look.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace occlusion {

// A file that cannot be read or does not say what it should.
// what() is "<path>:<line>: <reason>", or "<path>: <reason>" when line is 0.
struct InputError : std::runtime_error {
  InputError(std::string path, std::size_t line, std::string reason);

  std::string path;
  std::size_t line = 0;  // 1-based; 0 = unknown or the whole file
  std::string reason;    // the message without the location prefix
};

// An output that could not be written. what() is "<path>: <reason>".
struct OutputError : std::runtime_error {
  OutputError(std::string path, std::string reason);

  std::string path;
  std::string reason;
};

}  // namespace occlusion
