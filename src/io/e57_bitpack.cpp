// Bits least significant first, a byte at a time from the stream's runs.

#include "e57_bitpack.hpp"

#include <cstring>
#include <limits>

namespace occlusion::detail {

std::uint64_t bits_needed(const E57Field& field, std::uint64_t records) {
  if (field.bits != 0 && records > std::numeric_limits<std::uint64_t>::max() / field.bits) {
    return std::numeric_limits<std::uint64_t>::max();
  }
  return records * field.bits;
}

std::uint64_t E57FieldReader::take_up_to_32(unsigned count) {
  while (held_count_ < count) {
    std::uint64_t byte = 0;
    while (run_ < runs_->size() && at_ == (*runs_)[run_].size) {
      ++run_;
      at_ = 0;
    }
    if (run_ < runs_->size()) byte = (*runs_)[run_].data[at_++];
    held_ |= byte << held_count_;
    held_count_ += 8;
  }
  const std::uint64_t value = count == 0 ? 0 : held_ & ((std::uint64_t{1} << count) - 1);
  held_ >>= count;
  held_count_ -= count;
  return value;
}

std::uint64_t E57FieldReader::take(unsigned count) {
  if (count <= 32) return take_up_to_32(count);
  const std::uint64_t low = take_up_to_32(32);
  return low | take_up_to_32(count - 32) << 32;
}

double E57FieldReader::next(bool& raw_ok) {
  raw_ok = true;
  if (field_.kind == E57Field::Kind::kFloat) {
    const std::uint64_t raw = take(field_.bits);
    if (field_.single) {
      const auto word = static_cast<std::uint32_t>(raw);
      float value;
      std::memcpy(&value, &word, sizeof value);
      return value;
    }
    double value;
    std::memcpy(&value, &raw, sizeof value);
    return value;
  }
  const std::uint64_t raw = take(field_.bits);
  const std::uint64_t span =
      static_cast<std::uint64_t>(field_.maximum) - static_cast<std::uint64_t>(field_.minimum);
  raw_ok = raw <= span;
  const auto value = static_cast<std::int64_t>(static_cast<std::uint64_t>(field_.minimum) + raw);
  if (field_.kind == E57Field::Kind::kInteger) return static_cast<double>(value);
  return static_cast<double>(value) * field_.scale + field_.offset;
}

}  // namespace occlusion::detail
