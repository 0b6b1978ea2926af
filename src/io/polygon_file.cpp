#include "occlusion/io/polygon_file.hpp"

#include <cmath>
#include <ostream>
#include <stdexcept>

#include "number_text.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion {
namespace {

using Polygon = std::vector<Eigen::Vector3d>;

void finish_polygon(Polygon& polygon, std::size_t last_line, const std::string& path,
                    std::vector<Polygon>& polygons) {
  if (polygon.empty()) return;
  if (polygon.size() < 3) {
    throw InputError(path, last_line,
                     "polygon has " + std::to_string(polygon.size()) +
                         " points, needs at least 3 (a blank line ends a polygon)");
  }
  polygons.push_back(std::move(polygon));
  polygon.clear();
}

}  // namespace

std::vector<Polygon> read_polygons(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  std::vector<Polygon> polygons;
  Polygon current;
  std::size_t last_point_line = 0;
  detail::Lines lines(bytes);
  std::string_view line;
  while (lines.next(line)) {
    const std::size_t comment = line.find('#');
    const bool has_comment = comment != std::string_view::npos;
    if (has_comment) line = line.substr(0, comment);
    if (detail::is_blank_line(line)) {
      if (!has_comment) finish_polygon(current, last_point_line, path, polygons);
      continue;
    }
    detail::Tokens tokens(line);
    Eigen::Vector3d point;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view token = tokens.next();
      if (token.empty()) {
        throw InputError(
            path, lines.number(),
            "a point needs 3 coordinates (x y z), this line has " + std::to_string(axis));
      }
      if (!detail::parse_double(token, point[axis]) || !std::isfinite(point[axis])) {
        throw InputError(path, lines.number(),
                         "coordinate " + detail::quoted(token) + " is not a finite number");
      }
    }
    if (!tokens.next().empty()) {
      throw InputError(path, lines.number(),
                       "a point has 3 coordinates (x y z), this line has more");
    }
    current.push_back(point);
    last_point_line = lines.number();
  }
  finish_polygon(current, last_point_line, path, polygons);
  if (polygons.empty()) throw InputError(path, 0, "no polygons (the file has no points)");
  return polygons;
}

void write_polygons(const std::string& path, const std::vector<Polygon>& polygons) {
  if (polygons.empty()) throw std::invalid_argument("write_polygons: no polygons");
  std::string text = "# openings: x y z per line, a blank line between polygons\n";
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    if (polygons[p].size() < 3) {
      throw std::invalid_argument("write_polygons: polygon " + std::to_string(p) + " has " +
                                  std::to_string(polygons[p].size()) + " points, needs 3");
    }
    if (p > 0) text += '\n';
    for (const Eigen::Vector3d& point : polygons[p]) {
      if (!point.allFinite()) {
        throw std::invalid_argument("write_polygons: polygon " + std::to_string(p) +
                                    " has a non-finite point");
      }
      for (int axis = 0; axis < 3; ++axis) {
        if (axis > 0) text += ' ';
        detail::append_number(text, point[axis]);
      }
      text += '\n';
    }
  }
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace occlusion
