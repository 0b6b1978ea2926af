#pragma once
// How much a PCD header may declare. The reader checks a header against these
// and the file's size before anything is allocated (docs/formats.md, "Limits").

#include <cstdint>
#include <string>

namespace occlusion::detail {

// WIDTH, HEIGHT, POINTS, SIZE and COUNT are 32-bit unsigned in PCL.
inline constexpr std::uint64_t kMaxPcdHeaderNumber = 0xFFFFFFFFu;
// Values in one field (COUNT): histogram descriptors such as FPFH (33) or
// VFH (308) are the long ones; 65,536 is far beyond any in PCL.
inline constexpr std::uint64_t kMaxPcdFieldCount = 65536;
// Point data a header may claim whatever the file's size: harmless to
// allocate, and then the parse itself reports a short file by its line.
inline constexpr std::uint64_t kPcdExpansionFloorBytes = std::uint64_t{64} << 20;
// binary_compressed: LZF can expand ~88-fold on constant runs, so a small
// file could claim gigabytes (a decompression bomb). Real scans compress 2-4
// fold (a Kinect frame, a third NaN: 3.1); 32-fold is allowed, and any block
// may expand to kPcdExpansionFloorBytes.
inline constexpr std::uint64_t kMaxPcdExpansionRatio = 32;

// The most bytes `compressed` bytes of binary_compressed data may decode to.
inline std::uint64_t most_pcd_decoded_bytes(std::uint64_t compressed) {
  const std::uint64_t scaled = compressed * kMaxPcdExpansionRatio;
  return scaled > kPcdExpansionFloorBytes ? scaled : kPcdExpansionFloorBytes;
}

// The rule above, for messages.
inline std::string pcd_expansion_rule() {
  return "a compressed PCD may expand " + std::to_string(kMaxPcdExpansionRatio) + "-fold or to " +
         std::to_string(kPcdExpansionFloorBytes >> 20) + " MiB";
}

}  // namespace occlusion::detail
