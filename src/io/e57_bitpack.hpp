#pragma once
// E57's bitPackCodec: each field's values, one after another, in a stream of
// bits read least significant first (byte by byte, so the word size the
// writer used does not matter). Integer and ScaledInteger values take
// E57Field::bits bits each, stored as value - minimum; Float values are IEEE
// single or double.

#include <cstdint>

#include "e57_scan.hpp"
#include "e57_section.hpp"

namespace occlusion::detail {

// The values of one field, in record order. The caller checks first that the
// stream holds bits * records bits (bits_needed); past its end the reader
// gives zeros rather than reading beyond.
class E57FieldReader {
 public:
  E57FieldReader(const E57Field& field, const E57Stream& stream)
      : field_(field), runs_(&stream.runs) {}

  // The next value (ScaledInteger scaled); for the integer kinds, `raw_ok` is
  // false when the stored value exceeds the field's maximum.
  double next(bool& raw_ok);

 private:
  std::uint64_t take(unsigned count);
  std::uint64_t take_up_to_32(unsigned count);

  const E57Field& field_;
  const std::vector<E57Run>* runs_;
  std::size_t run_ = 0, at_ = 0;
  std::uint64_t held_ = 0;  // bits read ahead, least significant first
  unsigned held_count_ = 0;
};

// Bits `records` values of `field` take, saturated at UINT64_MAX.
std::uint64_t bits_needed(const E57Field& field, std::uint64_t records);

}  // namespace occlusion::detail
