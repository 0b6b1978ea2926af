#pragma once
// A convex polygon turned into triangles the way the thesis does it (3.2.2):
// the area-weighted centroid of the polygon, then one triangle from the
// centroid to each edge. Plane coordinates in, indices out, so the caller
// decides where the 3-D vertices live.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace occlusion {

// Signed area by the shoelace formula, A = 1/2 sum(x_i y_{i+1} - x_{i+1} y_i):
// positive for counter-clockwise vertices.
double polygon_signed_area(const std::vector<Eigen::Vector2d>& polygon);

// C = 1/(6A) sum((p_i + p_{i+1}) (x_i y_{i+1} - x_{i+1} y_i)), the seed's
// formulas. Summed relative to the first vertex, which gives the same centroid
// without the cancellation of large coordinates. Either winding.
// Throws std::invalid_argument for fewer than 3 vertices, a non-finite vertex
// or zero area.
Eigen::Vector2d polygon_centroid_2d(const std::vector<Eigen::Vector2d>& polygon);

// The fan over a polygon whose `count` vertices are first, first + 1, ... in
// order and whose centroid is vertex `centre`: triangle i is
// (centre, first + i, first + (i + 1) % count), so the triangles keep the
// polygon's winding. Throws std::invalid_argument for count < 3.
std::vector<std::array<std::uint32_t, 3>> fan_triangles(std::uint32_t centre, std::uint32_t first,
                                                        std::size_t count);

}  // namespace occlusion
