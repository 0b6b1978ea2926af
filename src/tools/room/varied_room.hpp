#pragma once
// A room that differs with every seed: its outline (office, conference
// room, hallway, open plan or an L-shaped lounge) and size, its openings
// (doors and windows on walls drawn at random), and its furniture (tables
// with chairs around them, sofas, bookcases, boards, columns, ceiling beams
// and clutter), counts and places drawn per room. Every one of the 13 S3DIS
// classes can appear; colours come from palette.hpp. The same seed,
// spacing and noise give the same bytes.

#include <cstdint>
#include <string>
#include <vector>

#include "room_model.hpp"

namespace occlusion::room {

struct VariedRoom {
  std::string kind;  // the floor plan's kind, e.g. "hallway"
  std::vector<Instance> instances;
  // The window and door outlines on their walls (io/polygon_file.hpp).
  std::vector<std::vector<Eigen::Vector3d>> openings;
};

VariedRoom varied_room(std::uint64_t seed, double spacing, double sensor_noise);

}  // namespace occlusion::room
