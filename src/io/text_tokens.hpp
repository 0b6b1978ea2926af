#pragma once
// Whitespace tokens and strict numbers for the text readers (plain text, PLY
// ascii, PCD ascii, polygon files, OBJ). Strict: a token is a number only if all of
// it is, so `1.5x` or a stray control byte is an error rather than a 1.5.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>

namespace occlusion::detail {

inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Splits one line into whitespace-separated tokens without allocating.
class Tokens {
 public:
  explicit Tokens(std::string_view line) : rest_(line) {}

  // The next token, or an empty view at the end of the line.
  std::string_view next() {
    std::size_t begin = 0;
    while (begin < rest_.size() && is_blank(rest_[begin])) ++begin;
    std::size_t end = begin;
    while (end < rest_.size() && !is_blank(rest_[end])) ++end;
    const std::string_view token = rest_.substr(begin, end - begin);
    rest_.remove_prefix(end);
    return token;
  }
  // What next() has not consumed yet, leading and trailing blanks removed.
  std::string_view rest() const {
    std::size_t begin = 0;
    while (begin < rest_.size() && is_blank(rest_[begin])) ++begin;
    std::size_t end = rest_.size();
    while (end > begin && is_blank(rest_[end - 1])) --end;
    return rest_.substr(begin, end - begin);
  }

 private:
  std::string_view rest_;
};

// Where lines end. Text ends a line at LF, CR LF or a lone CR (old Mac
// files, and files whose tools mixed the conventions): read as one line, a
// CR-separated file ran its statements together, and readers that ignored
// trailing fields lost the later ones. Headers followed by binary data (PLY,
// PCD) end lines at LF only, keeping a CR in the line: their byte counts
// find where the data starts, and its first byte may be an LF.
enum class LineEnds { kAny, kLfOnly };

// Steps through text line by line, counting from 1, with or without a final newline.
class Lines {
 public:
  explicit Lines(std::string_view text, std::size_t first_number = 1,
                 LineEnds ends = LineEnds::kAny)
      : text_(text), next_number_(first_number), ends_(ends) {}

  bool next(std::string_view& line) {
    if (position_ >= text_.size()) return false;
    std::size_t end = ends_ == LineEnds::kAny ? text_.find_first_of("\r\n", position_)
                                              : text_.find('\n', position_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(position_, end - position_);
    position_ = end + 1;
    if (end < text_.size() && text_[end] == '\r' && position_ < text_.size() &&
        text_[position_] == '\n') {
      ++position_;
    }
    number_ = next_number_++;
    return true;
  }
  std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  std::size_t next_number_;
  LineEnds ends_;
  std::size_t number_ = 0;
};

// Text files saved by Windows tools may start with a UTF-8 byte-order mark.
inline std::string_view without_byte_order_mark(std::string_view text) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) {
    text.remove_prefix(kByteOrderMark.size());
  }
  return text;
}

inline bool is_blank_line(std::string_view line) {
  for (const char c : line) {
    if (!is_blank(c)) return false;
  }
  return true;
}

// from_chars does not accept a leading '+', which some exporters write.
inline std::string_view without_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') {
    token.remove_prefix(1);
  }
  return token;
}

// Accepts what from_chars accepts, including nan and inf (the callers decide
// what a non-finite value means). A value too large for a double is infinite.
inline bool parse_double(std::string_view token, double& value) {
  token = without_plus(token);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  if (stop != end) return false;
  if (error == std::errc::result_out_of_range) {
    // from_chars leaves the value unset on overflow and underflow alike; strtod
    // tells them apart (HUGE_VAL versus a tiny number).
    const std::string copy(token);
    value = std::strtod(copy.c_str(), nullptr);
    return true;
  }
  return error == std::errc();
}

// A whole number, written as an integer or as a decimal with no fraction
// (`3` or `3.000000`: numpy's savetxt writes labels the second way).
inline bool parse_whole_number(std::string_view token, std::int64_t& value) {
  token = without_plus(token);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  if (error == std::errc() && stop == end) return true;
  double real = 0;
  if (!parse_double(token, real) || !std::isfinite(real) || real != std::floor(real) ||
      std::fabs(real) > 9.0e15) {
    return false;
  }
  value = static_cast<std::int64_t>(real);
  return true;
}

// A token quoted for an error message: control bytes shown as \xNN (the corrupt
// S3DIS line is invisible otherwise), long tokens shortened.
inline std::string quoted(std::string_view token) {
  constexpr std::size_t kMaxShown = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    const auto byte = static_cast<unsigned char>(token[i]);
    if (byte < 0x20 || byte >= 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += static_cast<char>(byte);
    }
  }
  if (token.size() > kMaxShown) out += "...";
  return out + "'";
}

}  // namespace occlusion::detail
