#include "floor_plan.hpp"

#include <array>
#include <cmath>

namespace occlusion::room {

namespace {

double between(Rng& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.uniform();
}

// Walls along a counter-clockwise outline: the room is on each edge's left.
std::vector<Wall> walls_of(const std::vector<Eigen::Vector2d>& outline) {
  std::vector<Wall> walls;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector2d a = outline[i];
    const Eigen::Vector2d b = outline[(i + 1) % outline.size()];
    const Eigen::Vector2d direction = (b - a).normalized();
    walls.push_back({{a.x(), a.y(), 0},
                     {direction.x(), direction.y(), 0},
                     {-direction.y(), direction.x(), 0},
                     (b - a).norm()});
  }
  return walls;
}

// A point in the union of the pieces (or on its edge).
bool on_floor(const std::vector<Rect>& pieces, double x, double y) {
  constexpr double kEdge = 1e-9;
  for (const Rect& p : pieces) {
    if (x >= p.x0 - kEdge && x <= p.x1 + kEdge && y >= p.y0 - kEdge && y <= p.y1 + kEdge)
      return true;
  }
  return false;
}

}  // namespace

bool FloorPlan::holds(const Rect& r) const {
  // An L's pieces are convex and meet along a whole edge, so a rectangle
  // whose corners and centre are on the floor lies on it.
  const std::array<Eigen::Vector2d, 5> probes{
      Eigen::Vector2d(r.x0, r.y0), Eigen::Vector2d(r.x1, r.y0), Eigen::Vector2d(r.x1, r.y1),
      Eigen::Vector2d(r.x0, r.y1), Eigen::Vector2d((r.x0 + r.x1) / 2, (r.y0 + r.y1) / 2)};
  for (const Eigen::Vector2d& p : probes) {
    if (!on_floor(pieces, p.x(), p.y())) return false;
  }
  // A rectangle spanning the L's notch has its corners on the floor but
  // crosses the missing corner: test the notch's own corner too.
  if (pieces.size() == 2) {
    const Rect& upper = pieces[1];
    const Eigen::Vector2d notch(upper.x1, upper.y0);
    if (notch.x() > r.x0 && notch.x() < r.x1 && notch.y() > r.y0 && notch.y() < r.y1) return false;
  }
  return true;
}

FloorPlan random_floor_plan(Rng& rng) {
  FloorPlan plan;
  const int kind = static_cast<int>(rng.uniform() * 5.0);
  double width = 0;
  double depth = 0;
  switch (kind) {
    case 0:
      plan.kind = "office";
      width = between(rng, 3.0, 6.5);
      depth = between(rng, 3.0, 5.5);
      plan.height = between(rng, 2.6, 3.2);
      break;
    case 1:
      plan.kind = "conferenceRoom";
      width = between(rng, 5.5, 9.0);
      depth = between(rng, 4.5, 7.0);
      plan.height = between(rng, 2.8, 3.5);
      break;
    case 2:
      plan.kind = "hallway";
      width = between(rng, 7.0, 14.0);
      depth = between(rng, 1.6, 2.6);
      plan.height = between(rng, 2.6, 3.2);
      break;
    case 3:
      plan.kind = "openspace";
      width = between(rng, 9.0, 14.0);
      depth = between(rng, 7.0, 10.0);
      plan.height = between(rng, 3.0, 4.0);
      break;
    default:
      plan.kind = "lounge";
      width = between(rng, 6.0, 10.0);
      depth = between(rng, 5.0, 8.0);
      plan.height = between(rng, 2.7, 3.4);
      break;
  }
  if (plan.kind == "lounge") {
    // An L: the bounding box without its north-east corner.
    const double notch_x = width - between(rng, 0.35, 0.55) * width;
    const double notch_y = depth - between(rng, 0.35, 0.55) * depth;
    plan.pieces = {{0, 0, width, notch_y}, {0, notch_y, notch_x, depth}};
    plan.walls = walls_of(
        {{0, 0}, {width, 0}, {width, notch_y}, {notch_x, notch_y}, {notch_x, depth}, {0, depth}});
  } else {
    plan.pieces = {{0, 0, width, depth}};
    plan.walls = walls_of({{0, 0}, {width, 0}, {width, depth}, {0, depth}});
  }
  return plan;
}

}  // namespace occlusion::room
