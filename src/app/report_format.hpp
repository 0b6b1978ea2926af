#pragma once
// Numbers and text as the jobs' CSV and Markdown reports print them (internal
// to app/). An undefined figure is printed as `missing` (empty in CSV, a dash
// in Markdown), never as 0 or NaN, which a reader would average in.

#include <optional>
#include <string>

namespace occlusion::job {

// printf-style, one double: format_number("%.4f", x).
std::string format_number(const char* pattern, double value);
std::string format_number(const char* pattern, const std::optional<double>& value,
                          const char* missing);
// A Markdown table cell: a pipe would end it.
std::string markdown_cell(const std::string& text);

}  // namespace occlusion::job
