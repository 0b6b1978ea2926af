#pragma once
// What a generated room is made of: labelled instances of coloured points,
// sampled from axis-aligned boxes and rectangles.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace occlusion::room {

using Colour = std::array<int, 3>;

struct Box {
  Eigen::Vector3d lo, hi;
  bool contains(const Eigen::Vector3d& p, double margin) const {
    return (p.array() > lo.array() - margin).all() && (p.array() < hi.array() + margin).all();
  }
};

// Axis-aligned box faces, to leave out those resting on the floor or a wall.
enum Face : unsigned { kMinX = 1, kMaxX = 2, kMinY = 4, kMaxY = 8, kMinZ = 16, kMaxZ = 32 };

struct Point {
  Eigen::Vector3d position;
  Colour colour;
};

using Triangle3d = std::array<Eigen::Vector3d, 3>;

// One object: an S3DIS class name, its points and the surfaces they were
// sampled from (exact, without the points' noise and jitter; openings cut
// out), so that a virtual scanner can scan the same room (--mesh).
struct Instance {
  std::string class_name;
  std::vector<Point> points;
  std::vector<Triangle3d> triangles;
};

// A piece of furniture before sampling: its boxes hide the surfaces they
// touch, so every part is registered before any surface is sampled.
struct Part {
  std::string class_name;
  std::vector<Box> boxes;
  std::vector<unsigned> skipped_faces;  // per box; missing entries skip none
  Colour colour;
};

}  // namespace occlusion::room
