#pragma once
// A room's outline: an axis-aligned polygon (a rectangle or an L), its
// height, and the walls along its edges. The inner corner of its bounding
// box is at the origin, z up.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "occlusion/core/random.hpp"

namespace occlusion::room {

struct Rect {
  double x0, y0, x1, y1;
  bool overlaps(const Rect& other) const {
    return x0 < other.x1 && other.x0 < x1 && y0 < other.y1 && other.y0 < y1;
  }
};

// One wall: from `start`, `length` metres along `along` (a unit x or y axis),
// its room side towards `inward`.
struct Wall {
  Eigen::Vector3d start, along, inward;
  double length;
  Eigen::Vector3d at(double s) const { return start + s * along; }
};

struct FloorPlan {
  std::string kind;          // office, conferenceRoom, hallway, openspace, lounge (an L)
  double height = 3.0;       // floor to ceiling
  std::vector<Rect> pieces;  // disjoint rectangles whose union is the floor
  std::vector<Wall> walls;   // the outline's edges, counter-clockwise
  // True when the rectangle lies on the floor (inside the outline).
  bool holds(const Rect& r) const;
};

// A seeded outline: the kind, then its size; every kind is drawn as often.
FloorPlan random_floor_plan(Rng& rng);

}  // namespace occlusion::room
