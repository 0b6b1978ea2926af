#pragma once
// Whole files in memory: the readers parse from a buffer, so that truncation
// is a length comparison, a byte offset is an index and a line is a view.
// Every input file is opened here (the readers of io/, the config and the
// class mapping of app/), so the rules below hold for all.

#include <cstdint>
#include <string>

#include "occlusion/core/large_buffer.hpp"

namespace occlusion {

// The largest input file read into memory: 16 GiB. Bigger is no scan we know
// of (S3DIS's largest room is 0.3 GB) and would exhaust a workstation.
inline constexpr std::uint64_t kMaxInputFileBytes = std::uint64_t{16} << 30;

// The file's bytes. InputError if it is missing, unreadable, a directory or
// anything but a regular file (a FIFO would block, /dev/zero never ends), or
// larger than kMaxInputFileBytes. Opened without blocking, so that a FIFO is
// refused, not waited on.
// Bytes is std::string or LargeString (core/large_buffer.hpp: a big scan's
// bytes in huge pages, first touched in hundreds of faults, not thousands).
template <class Bytes = std::string>
Bytes read_file_bytes(const std::string& path);

}  // namespace occlusion
