#pragma once
// Numbers appended to text the writers build: std::to_chars, so no locale and
// no stream formatting (a stream's number formatting took a third of -moc's
// writing).

#include <charconv>
#include <string>

namespace occlusion::detail {

// Any integer, or the shortest text that reads back as exactly the same float
// or double.
template <class Number>
void append_number(std::string& text, Number value) {
  char digits[32];
  text.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
}

// printf's %.<significant>g: what a C++ stream with that precision writes.
inline void append_significant(std::string& text, double value, int significant) {
  char digits[48];
  text.append(digits, std::to_chars(digits, digits + sizeof digits, value,
                                    std::chars_format::general, significant)
                          .ptr);
}

}  // namespace occlusion::detail
