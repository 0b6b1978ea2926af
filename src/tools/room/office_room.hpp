#pragma once
// The fixed office every demo and test has used: 6 x 5 x 3 m, z up, its
// inner corner at the origin. The north wall (y = 5) has a window hole, the
// west wall (x = 0) a door hole reaching the floor. The window is a frame
// around its hole, the door a leaf standing 30 degrees open into the room.
// Furniture is boxes: a table, four chairs, a bookcase against the east
// wall, a board on the south wall and four clutter objects. The seed moves
// only the sampling jitter; the same seed and spacing give the same bytes.

#include <cstdint>
#include <vector>

#include "room_model.hpp"

namespace occlusion::room {

std::vector<Instance> office_room(std::uint64_t seed, double spacing, double sensor_noise);

// The window and door outlines, for --openings (io/polygon_file.hpp).
std::vector<std::vector<Eigen::Vector3d>> office_openings();

}  // namespace occlusion::room
