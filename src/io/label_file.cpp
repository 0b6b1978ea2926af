#include "occlusion/io/label_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <limits>

#include "file_names.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion {

namespace {

// The text cloud reader's comments too, so that telling the two apart by the
// first data line sees the same line.
bool is_skipped(std::string_view line) {
  detail::Tokens tokens(line);
  const std::string_view first = tokens.next();
  return first.empty() || first[0] == '#' || first.substr(0, 2) == "//";
}

}  // namespace

std::vector<std::int32_t> read_label_file(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  std::vector<std::int32_t> labels;
  detail::Lines lines(detail::without_byte_order_mark(bytes));
  std::string_view line;
  while (lines.next(line)) {
    if (is_skipped(line)) continue;
    detail::Tokens tokens(line);
    const std::string_view token = tokens.next();
    if (!tokens.next().empty()) {
      throw InputError(path, lines.number(),
                       "a label file has one number per line, this line has more");
    }
    std::int64_t value = 0;
    if (!detail::parse_whole_number(token, value)) {
      throw InputError(path, lines.number(),
                       "label " + detail::quoted(token) + " is not a whole number");
    }
    if (value < -1 || value > std::numeric_limits<std::int32_t>::max()) {
      throw InputError(path, lines.number(),
                       "label " + std::to_string(value) + " is out of range (-1 is no label)");
    }
    labels.push_back(static_cast<std::int32_t>(value));
  }
  if (labels.empty()) throw InputError(path, 0, "no labels");
  return labels;
}

void write_label_file(const std::string& path, const std::vector<std::int32_t>& labels) {
  write_file_atomically(path, [&](std::ostream& out) {
    std::string text;
    text.reserve(labels.size() * 3);
    for (const auto label : labels) {
      text += std::to_string(label);
      text += '\n';
    }
    out << text;
  });
}

bool is_label_file(const std::string& path) {
  const std::string extension = detail::lower_extension(path);
  if (extension == ".labels" || extension == ".label") return true;
  if (extension != ".txt" || std::filesystem::is_directory(path)) return false;
  const std::string bytes = read_file_bytes(path);
  detail::Lines lines(detail::without_byte_order_mark(bytes));
  std::string_view line;
  while (lines.next(line)) {
    if (is_skipped(line)) continue;
    detail::Tokens tokens(line);
    tokens.next();
    return tokens.next().empty();
  }
  return false;
}

}  // namespace occlusion
