#include "occlusion/io/class_names_file.hpp"

#include <algorithm>
#include <map>

#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion {

std::vector<std::string> parse_class_names(std::string_view text, const std::string& source) {
  std::vector<std::string> names;
  std::map<std::string, std::size_t> line_of;
  detail::Lines lines(detail::without_byte_order_mark(text));
  std::string_view line;
  std::size_t blank_line = 0;  // the first blank line so far, fine only at the end
  while (lines.next(line)) {
    detail::Tokens tokens(line);
    const std::string_view name = tokens.rest();
    if (name.empty()) {
      if (blank_line == 0) blank_line = lines.number();
      continue;
    }
    if (blank_line != 0) {
      throw InputError(source, blank_line,
                       "blank line: line k names label k - 1, so it would shift the names "
                       "after it onto the wrong labels");
    }
    const auto [entry, inserted] = line_of.try_emplace(std::string(name), lines.number());
    if (!inserted) {
      throw InputError(source, lines.number(),
                       "class '" + entry->first + "' is named twice (first on line " +
                           std::to_string(entry->second) + ")");
    }
    names.emplace_back(name);
  }
  if (names.empty()) throw InputError(source, 0, "no class names");
  return names;
}

std::vector<std::string> read_class_names_file(const std::string& path) {
  return parse_class_names(read_file_bytes(path), path);
}

void apply_class_names_file(PointCloud& cloud, const std::string& cloud_name,
                            const std::string& names_path) {
  if (!cloud.has_labels()) {
    throw InputError(cloud_name, 0,
                     "has no labels for the class_names file " + names_path + " to name");
  }
  std::vector<std::string> names = read_class_names_file(names_path);
  if (!cloud.class_names.empty()) {
    if (cloud.class_names == names) return;
    throw InputError(cloud_name, 0,
                     "names its own " + std::to_string(cloud.class_names.size()) +
                         " classes, which differ from the class_names file " + names_path + "'s " +
                         std::to_string(names.size()) +
                         " (leave the file out to use the cloud's names)");
  }
  const std::int32_t highest = *std::max_element(cloud.labels.begin(), cloud.labels.end());
  if (highest >= static_cast<std::int32_t>(names.size())) {
    throw InputError(names_path, 0,
                     "names labels 0.." + std::to_string(names.size() - 1) + ", but " + cloud_name +
                         " has label " + std::to_string(highest));
  }
  cloud.class_names = std::move(names);
}

}  // namespace occlusion
