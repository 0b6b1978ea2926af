#pragma once
// Openings file: the windows and doors through which a ray leaves the scene
// (the config key polygon_path, option --polygon-path). Points picked on each
// opening's boundary, one polygon after another:
//
//   # window, north wall          <- `#` starts a comment, to the end of the line
//   2.0 5.0 0.9
//   3.6 5.0 0.9                   <- one point per line: x y z, in scene units
//   3.6 5.0 2.2
//   2.0 5.0 2.2
//                                 <- one or more blank lines end a polygon
//   0.0 0.6 0.0
//   ...
//
// UTF-8 (ASCII in practice) text; CRLF line ends are accepted. Points are in
// boundary order; the polygon closes itself (do not repeat the first point).
// A polygon needs at least 3 points; they should lie roughly in one plane
// (core/polygon.hpp fits a plane to them). A comment line does not end a
// polygon, only a blank (or whitespace-only) line does. docs/formats.md has
// the same description.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace occlusion {

// InputError with the 1-based line for a line that is not exactly three finite
// numbers, a polygon with fewer than 3 points (the line of its last point), and
// a file with no polygons.
std::vector<std::vector<Eigen::Vector3d>> read_polygons(const std::string& path);

// Writes the format above, numbers with the fewest digits that read back
// exactly. std::invalid_argument for a polygon with fewer than 3 points or a
// non-finite coordinate, or no polygons; OutputError if the file cannot be
// written. Written atomically (atomic_file.hpp).
void write_polygons(const std::string& path,
                    const std::vector<std::vector<Eigen::Vector3d>>& polygons);

}  // namespace occlusion
