#pragma once
// An E57 CompressedVector binary section: a 32-byte header, then packets
// (data, index, empty). Each data packet carries one buffer per bytestream
// (one per prototype field); a bytestream is its buffers end to end across
// the data packets, whatever the packet boundaries split.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "e57_pages.hpp"

namespace occlusion::detail {

// Bytes of a bytestream that lie in one page, in stream order.
struct E57Run {
  const unsigned char* data = nullptr;
  std::size_t size = 0;
};

struct E57Stream {
  std::vector<E57Run> runs;
  std::uint64_t bytes = 0;
  std::uint64_t buffers = 0;  // data packets that carry some of its bytes
};

// A section's bytestreams and where it lies (logical offsets, [start, end)).
struct E57Section {
  std::vector<E57Stream> streams;
  std::uint64_t start = 0, end = 0;
};

// The `stream_count` bytestreams of the section at `physical_offset`; `what`
// names the section's XML element in errors. InputError for a header that is
// not a CompressedVector's, a section or packet that runs past the file or
// the section, a data packet whose buffer count differs from the prototype's
// fields or whose buffers overrun it, an unknown packet type. Nothing is
// copied: the runs point into the file's bytes.
E57Section read_compressed_vector(const E57Pages& pages, std::uint64_t physical_offset,
                                  std::size_t stream_count, const std::string& what);

}  // namespace occlusion::detail
