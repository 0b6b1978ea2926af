#include "occlusion/io/obj_reader.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh_checks.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion {
namespace {

constexpr std::uint32_t kUnresolvedGroup = std::numeric_limits<std::uint32_t>::max();

using detail::is_blank;
using detail::Tokens;

// Corner indices are plain integers: unlike detail::parse_whole_number, `3.0`
// is not a vertex reference.
bool parse_integer(std::string_view token, long long& value) {
  token = detail::without_plus(token);
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  return error == std::errc() && stop == end && !token.empty();
}

// The texture and normal parts of a corner (`/t`, `/t/n`, `//n`) are not used,
// but a corner like `3/x` or `3/1/2/4` is a broken file, not something to skip.
bool valid_corner_suffix(std::string_view suffix) {
  int slashes = 0;
  for (const char c : suffix) {
    if (c == '/') {
      if (++slashes > 2) return false;
    } else if (!(c >= '0' && c <= '9') && c != '-' && c != '+') {
      return false;
    }
  }
  return true;
}

class ObjParser {
 public:
  ObjParser(std::string_view text, const std::string& source, MeshReadReport& report)
      : text_(text), source_(source), report_(report) {}

  TriangleMesh run() {
    for_each_logical_line();
    if (mesh_.faces.empty()) fail(0, "no faces (the file has no 'f' statement)");
    check_indices_in_range();
    detail::drop_degenerate_faces(
        mesh_, 1, [&](std::size_t f) { return "line " + std::to_string(face_line_[f]); }, source_,
        report_);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, std::string reason) const {
    throw InputError(source_, line, std::move(reason));
  }

  // Splits the text into lines, joins `\` continuations, and reports each
  // statement with the number of the line it starts on.
  void for_each_logical_line() {
    std::string joined;  // only used for continued lines, which are rare
    std::size_t joined_start = 0;
    detail::Lines lines(text_);
    std::string_view line;
    while (lines.next(line)) {
      const std::size_t line_number = lines.number();
      std::size_t content_end = line.size();
      while (content_end > 0 && is_blank(line[content_end - 1])) --content_end;
      if (content_end > 0 && line[content_end - 1] == '\\') {
        if (joined.empty()) joined_start = line_number;
        joined.append(line.data(), content_end - 1);
        joined.push_back(' ');
        continue;
      }
      if (!joined.empty()) {
        joined.append(line.data(), line.size());
        statement(joined, joined_start);
        joined.clear();
      } else {
        statement(line, line_number);
      }
    }
    if (!joined.empty()) statement(joined, joined_start);
  }

  void statement(std::string_view line, std::size_t line_number) {
    const std::size_t comment = line.find('#');
    if (comment != std::string_view::npos) line = line.substr(0, comment);
    Tokens tokens(line);
    const std::string_view keyword = tokens.next();
    if (keyword == "v") {
      vertex(tokens, line_number);
    } else if (keyword == "f") {
      face(tokens, line_number);
    } else if (keyword == "g" || keyword == "o") {
      group(tokens);
    }
  }

  void vertex(Tokens& tokens, std::size_t line_number) {
    double xyz[3];
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view token = tokens.next();
      if (token.empty()) {
        fail(line_number, "vertex has " + std::to_string(axis) + " coordinates, expected 3");
      }
      if (!detail::parse_double(token, xyz[axis])) {
        fail(line_number, "vertex coordinate '" + std::string(token) + "' is not a number");
      }
      if (!std::isfinite(xyz[axis])) {
        fail(line_number, "vertex coordinate '" + std::string(token) + "' is not finite");
      }
    }
    check_vertex_extras(tokens, line_number);
    mesh_.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  // After x y z a vertex may carry a weight (w) or a colour (r g b, r g b a:
  // MeshLab's and others' extension), which are not used. Anything else is
  // refused: text there is the sign of a broken file (statements run
  // together), not something to skip.
  void check_vertex_extras(Tokens& tokens, std::size_t line_number) {
    int extras = 0;
    for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
      double value = 0;
      if (!detail::parse_double(token, value)) {
        fail(line_number, "vertex has " + detail::quoted(token) +
                              " after its coordinates, where only numbers may follow (x y z "
                              "[w] or x y z r g b [a])");
      }
      ++extras;
    }
    if (extras == 2 || extras > 4) {
      fail(line_number, "vertex has " + std::to_string(3 + extras) +
                            " numbers, expected 3 (x y z), 4 (x y z w), 6 or 7 (x y z r g b "
                            "[a])");
    }
  }

  void face(Tokens& tokens, std::size_t line_number) {
    corners_.clear();
    for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
      corners_.push_back(corner_index(token, line_number));
    }
    if (corners_.size() < 3) {
      fail(line_number,
           "face has " + std::to_string(corners_.size()) + " vertices, needs at least 3");
    }
    const std::uint32_t group_id = current_group_id();
    for (std::size_t i = 1; i + 1 < corners_.size(); ++i) {
      mesh_.faces.push_back({corners_[0], corners_[i], corners_[i + 1]});
      mesh_.face_group.push_back(group_id);
      face_line_.push_back(line_number);
    }
  }

  // The 0-based vertex index of one face corner. A positive index past the
  // vertices read so far is accepted here and checked once the file is read.
  std::uint32_t corner_index(std::string_view token, std::size_t line_number) {
    const std::size_t slash = token.find('/');
    const std::string_view index_text = token.substr(0, slash);
    long long index = 0;
    if (!parse_integer(index_text, index) ||
        (slash != std::string_view::npos && !valid_corner_suffix(token.substr(slash)))) {
      fail(line_number, "face vertex '" + std::string(token) + "' is not a valid reference");
    }
    if (index == 0) fail(line_number, "face vertex index 0 is invalid (OBJ indices start at 1)");
    const auto defined = static_cast<long long>(mesh_.vertices.size());
    if (index < 0) {
      if (defined + index < 0) {
        fail(line_number, "relative face vertex index " + std::to_string(index) +
                              " is out of range (" + std::to_string(defined) +
                              " vertices defined so far)");
      }
      return static_cast<std::uint32_t>(defined + index);
    }
    if (index > static_cast<long long>(std::numeric_limits<std::uint32_t>::max())) {
      fail(line_number, "face vertex index " + std::to_string(index) + " is out of range");
    }
    return static_cast<std::uint32_t>(index - 1);
  }

  void group(Tokens& tokens) {
    std::string name;
    for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
      if (!name.empty()) name.push_back(' ');
      name.append(token.data(), token.size());
    }
    if (name.empty()) name = "default";
    if (name != current_group_) {
      current_group_ = std::move(name);
      current_group_id_ = kUnresolvedGroup;
    }
  }

  // Groups are numbered when their first face arrives, so empty groups never appear.
  std::uint32_t current_group_id() {
    if (current_group_id_ == kUnresolvedGroup) {
      const auto [entry, inserted] = group_ids_.try_emplace(
          current_group_, static_cast<std::uint32_t>(mesh_.group_names.size()));
      if (inserted) mesh_.group_names.push_back(current_group_);
      current_group_id_ = entry->second;
    }
    return current_group_id_;
  }

  void check_indices_in_range() const {
    const std::size_t count = mesh_.vertices.size();
    for (std::size_t f = 0; f < mesh_.faces.size(); ++f) {
      for (const std::uint32_t index : mesh_.faces[f]) {
        if (index >= count) {
          fail(face_line_[f], "face vertex index " + std::to_string(std::size_t{index} + 1) +
                                  " is out of range (the file has " + std::to_string(count) +
                                  " vertices)");
        }
      }
    }
  }

  std::string_view text_;
  const std::string& source_;
  MeshReadReport& report_;
  TriangleMesh mesh_;
  std::vector<std::size_t> face_line_;  // per triangle, for messages after parsing
  std::vector<std::uint32_t> corners_;  // scratch for the face being read
  std::string current_group_ = "default";
  std::uint32_t current_group_id_ = kUnresolvedGroup;
  std::unordered_map<std::string, std::uint32_t> group_ids_;
};

}  // namespace

TriangleMesh parse_obj(std::string_view text, const std::string& source_name,
                       MeshReadReport* report) {
  MeshReadReport local;
  return ObjParser(text, source_name, report != nullptr ? *report : local).run();
}

TriangleMesh read_obj(const std::string& path, MeshReadReport* report) {
  return parse_obj(read_file_bytes(path), path, report);
}

}  // namespace occlusion
