// A table per byte, or the SSE4.2 instruction where the CPU has it: a
// gigabyte scan's pages are all checked before anything else is read, and
// the instruction does that eight bytes a cycle.

#include "crc32c.hpp"

#include <array>
#include <cstring>

#if defined(__x86_64__)
#include <nmmintrin.h>
#endif

namespace occlusion::detail {
namespace {

constexpr std::array<std::uint32_t, 256> make_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1) != 0 ? (c >> 1) ^ 0x82F63B78u : c >> 1;
    table[i] = c;
  }
  return table;
}

constexpr std::array<std::uint32_t, 256> kTable = make_table();

std::uint32_t crc_by_table(std::uint32_t crc, const unsigned char* data, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) crc = kTable[(crc ^ data[i]) & 0xFFu] ^ (crc >> 8);
  return crc;
}

#if defined(__x86_64__)
__attribute__((target("sse4.2"))) std::uint32_t crc_by_instruction(std::uint32_t crc,
                                                                   const unsigned char* data,
                                                                   std::size_t size) {
  std::uint64_t wide = crc;
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    std::uint64_t word;
    std::memcpy(&word, data + i, 8);
    wide = _mm_crc32_u64(wide, word);
  }
  auto narrow = static_cast<std::uint32_t>(wide);
  for (; i < size; ++i) narrow = _mm_crc32_u8(narrow, data[i]);
  return narrow;
}
#endif

}  // namespace

std::uint32_t crc32c(const unsigned char* data, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
#if defined(__x86_64__)
  static const bool has_instruction = __builtin_cpu_supports("sse4.2");
  crc = has_instruction ? crc_by_instruction(crc, data, size) : crc_by_table(crc, data, size);
#else
  crc = crc_by_table(crc, data, size);
#endif
  return crc ^ 0xFFFFFFFFu;
}

}  // namespace occlusion::detail
