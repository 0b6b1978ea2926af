#pragma once
// Little-endian values read from a byte buffer (LAS), assembled by shifts so
// that any host reads them alike. The caller has checked that the bytes exist.

#include <cstdint>
#include <cstring>
#include <limits>

namespace occlusion::detail {

inline std::uint64_t load_le(const unsigned char* at, int bytes) {
  std::uint64_t value = 0;
  for (int k = 0; k < bytes; ++k) value |= std::uint64_t{at[k]} << (8 * k);
  return value;
}
inline std::uint8_t le_u8(const unsigned char* at) {
  return at[0];
}
inline std::uint16_t le_u16(const unsigned char* at) {
  return static_cast<std::uint16_t>(load_le(at, 2));
}
inline std::uint32_t le_u32(const unsigned char* at) {
  return static_cast<std::uint32_t>(load_le(at, 4));
}
inline std::uint64_t le_u64(const unsigned char* at) {
  return load_le(at, 8);
}
inline std::int32_t le_i32(const unsigned char* at) {
  return static_cast<std::int32_t>(le_u32(at));
}
inline double le_f64(const unsigned char* at) {
  static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559,
                "LAS doubles are IEEE 754 binary64");
  const std::uint64_t bits = le_u64(at);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace occlusion::detail
