#include "report_format.hpp"

#include <cstdio>

namespace occlusion::job {

std::string format_number(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string format_number(const char* pattern, const std::optional<double>& value,
                          const char* missing) {
  return value ? format_number(pattern, *value) : missing;
}

std::string markdown_cell(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

}  // namespace occlusion::job
