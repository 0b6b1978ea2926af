#pragma once
// Little-endian values for the binary PLY writers (clouds and meshes).
//
// Bytes are produced least significant first with shifts, which yields
// little-endian on any host: no byte swapping needed and no host-endianness
// test to get wrong. Where the bytes go is the caller's choice (a growing
// chunk, or a cursor into a buffer sized up front), so the sink is a callable.

#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

namespace occlusion::detail {

// PutByte: callable as put_byte(char), once per byte in file order.
template <class PutByte>
class LittleEndianWriter {
 public:
  explicit LittleEndianWriter(PutByte put_byte) : put_byte_(std::move(put_byte)) {}

  void u8(std::uint8_t value) { put_byte_(static_cast<char>(value)); }
  void u32(std::uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) u8(static_cast<std::uint8_t>(value >> shift));
  }
  void i32(std::int32_t value) { u32(static_cast<std::uint32_t>(value)); }
  void f32(float value) {
    static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559,
                  "PLY float is IEEE 754 binary32");
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    u32(bits);
  }
  void f64(double value) {
    static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559,
                  "PLY double is IEEE 754 binary64");
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int shift = 0; shift < 64; shift += 8) u8(static_cast<std::uint8_t>(bits >> shift));
  }

 private:
  PutByte put_byte_;
};

}  // namespace occlusion::detail
