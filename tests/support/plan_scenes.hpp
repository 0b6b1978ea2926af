#pragma once
// Scenes whose best scan plan is known (scan planning, issue 28), built in
// code: rooms as inward-facing boxes (so a station inside sees the front of
// every face), solids as outward-facing ones (so inside_solid.hpp sees a
// station in them). Header-only so that only the suites that use it compile it.

#include <Eigen/Core>
#include <string>
#include <tuple>

#include "occlusion/core/mesh.hpp"
#include "support/scenes.hpp"

namespace occlusion::testing {

// The box [lo, hi], every face's normal (e1 x e2) pointing out of it
// (`inward` false: a solid) or into it (a room).
inline void add_facing_box(TriangleMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                           bool inward, const std::string& group) {
  const Eigen::Vector3d size = hi - lo;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    Eigen::Vector3d ea = Eigen::Vector3d::Zero(), eb = Eigen::Vector3d::Zero();
    ea[a] = size[a];
    eb[b] = size[b];
    for (int side = 0; side < 2; ++side) {
      Eigen::Vector3d corner = lo;
      if (side == 1) corner[axis] = hi[axis];
      // ea x eb points along +axis: the high side faces out that way.
      const bool out_along_axis = (side == 1) != inward;
      if (out_along_axis) {
        add_quad(mesh, corner, ea, eb, group);
      } else {
        add_quad(mesh, corner, eb, ea, group);
      }
    }
  }
}

// Two rooms joined by a door: A = [0, 6.25] x [0, 5] (the larger) and
// B = [6.25, 10] x [0, 5], 3 high; the wall between them (x = 6.25, no
// thickness) has a door 0.8 wide (y 2.1 to 2.9) and 2.1 high. Off a 0.5 grid,
// so no grid position stands in the wall or the door.
inline TriangleMesh two_rooms() {
  TriangleMesh mesh;
  add_facing_box(mesh, {0, 0, 0}, {10, 5, 3}, true, "room");
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  add_quad(mesh, {6.25, 0, 0}, 2.1 * y, 3 * z, "wall");
  add_quad(mesh, {6.25, 2.9, 0}, 2.1 * y, 3 * z, "wall");
  add_quad(mesh, {6.25, 2.1, 2.1}, 0.8 * y, 0.9 * z, "wall");
  return mesh;
}

// Two rooms joined by a door as a survey meets them: A = [0, 6] x [0, 5] and
// B = [6.2, 10] x [0, 5], 3 high, the wall between them 0.2 thick (x 6 to
// 6.2) with a door 0.8 wide (y 2.25 to 3.05) and 2.1 high, and a 1 x 0.6 x 2
// cabinet in each room. The best single station stands in the door, in a
// strip 0.2 wide (the door less 0.3 of clearance on each side), where a
// 0.5 grid does not fall.
inline TriangleMesh two_rooms_thick_wall() {
  TriangleMesh mesh;
  add_facing_box(mesh, {0, 0, 0}, {10, 5, 3}, true, "room");
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  // The wall's two sides around the door (A's facing -x, B's +x), its jambs
  // and the lintel's underside: no face lies on another (the room's walls,
  // floor and ceiling meet it edge to edge).
  for (const auto& [lo, width, height] : {std::tuple{Eigen::Vector3d(6, 0, 0), 2.25, 3.0},
                                          std::tuple{Eigen::Vector3d(6, 3.05, 0), 1.95, 3.0},
                                          std::tuple{Eigen::Vector3d(6, 2.25, 2.1), 0.8, 0.9}}) {
    add_quad(mesh, lo, height * z, width * y, "wall");
    add_quad(mesh, lo + 0.2 * x, width * y, height * z, "wall");
  }
  add_quad(mesh, {6, 2.25, 0}, 2.1 * z, 0.2 * x, "wall");
  add_quad(mesh, {6, 3.05, 0}, 0.2 * x, 2.1 * z, "wall");
  add_quad(mesh, {6, 2.25, 2.1}, 0.8 * y, 0.2 * x, "wall");
  // Cabinets: four sides and a top, facing out (their bottoms would lie on the floor).
  for (const Eigen::Vector3d& lo : {Eigen::Vector3d(2, 3.6, 0), Eigen::Vector3d(8, 1, 0)}) {
    const Eigen::Vector3d dx = 1.0 * x, dy = 0.6 * y, dz = 2.0 * z;
    add_quad(mesh, lo + dz, dx, dy, "cabinet");
    add_quad(mesh, lo, dz, dy, "cabinet");
    add_quad(mesh, lo + dx, dy, dz, "cabinet");
    add_quad(mesh, lo, dx, dz, "cabinet");
    add_quad(mesh, lo + dy, dz, dx, "cabinet");
  }
  return mesh;
}

// A 6 x 6 x 3 room with a 0.8 x 0.8 pillar in its middle, floor to ceiling:
// the floor and ceiling stop at the pillar, which has only its four sides, so
// every surface can be seen from somewhere.
inline TriangleMesh pillar_room() {
  TriangleMesh mesh;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  // Floor (facing up) and ceiling (facing down) around the footprint [2.6, 3.4]^2.
  for (const auto& [corner, a, b] : {std::tuple{Eigen::Vector3d(0, 0, 0), 6 * x, 2.6 * y},
                                     std::tuple{Eigen::Vector3d(0, 3.4, 0), 6 * x, 2.6 * y},
                                     std::tuple{Eigen::Vector3d(0, 2.6, 0), 2.6 * x, 0.8 * y},
                                     std::tuple{Eigen::Vector3d(3.4, 2.6, 0), 2.6 * x, 0.8 * y}}) {
    add_quad(mesh, corner, a, b, "floor");
    add_quad(mesh, corner + 3 * z, b, a, "ceiling");
  }
  add_quad(mesh, {0, 0, 0}, 6 * y, 3 * z, "wall");  // x = 0
  add_quad(mesh, {6, 0, 0}, 3 * z, 6 * y, "wall");  // x = 6
  add_quad(mesh, {0, 0, 0}, 3 * z, 6 * x, "wall");  // y = 0
  add_quad(mesh, {0, 6, 0}, 6 * x, 3 * z, "wall");  // y = 6
  // The pillar's sides, facing out.
  add_quad(mesh, {2.6, 2.6, 0}, 3 * z, 0.8 * y, "pillar");  // x = 2.6, -x
  add_quad(mesh, {3.4, 2.6, 0}, 0.8 * y, 3 * z, "pillar");  // x = 3.4, +x
  add_quad(mesh, {2.6, 2.6, 0}, 0.8 * x, 3 * z, "pillar");  // y = 2.6, -y
  add_quad(mesh, {2.6, 3.4, 0}, 3 * z, 0.8 * x, "pillar");  // y = 3.4, +y
  return mesh;
}

// An empty 4 x 4 x 3 room.
inline TriangleMesh empty_room() {
  TriangleMesh mesh;
  add_facing_box(mesh, {0, 0, 0}, {4, 4, 3}, true, "room");
  return mesh;
}

// An L-shaped room: [0, 10] x [0, 10] without the corner [5, 10] x [5, 10], 3 high.
inline TriangleMesh l_room() {
  TriangleMesh mesh;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  // Floor and ceiling: the square [0,5]^2 and the two arms.
  for (const auto& [corner, a, b] : {std::tuple{Eigen::Vector3d(0, 0, 0), 5 * x, 10 * y},
                                     std::tuple{Eigen::Vector3d(5, 0, 0), 5 * x, 5 * y}}) {
    add_quad(mesh, corner, a, b, "floor");
    add_quad(mesh, corner + 3 * z, b, a, "ceiling");
  }
  // Walls around the L, each facing in (e1 x e2 into the room).
  add_quad(mesh, {0, 0, 0}, 10 * y, 3 * z, "wall");  // x = 0
  add_quad(mesh, {0, 0, 0}, 3 * z, 10 * x, "wall");  // y = 0
  add_quad(mesh, {10, 0, 0}, 3 * z, 5 * y, "wall");  // x = 10
  add_quad(mesh, {5, 5, 0}, 5 * x, 3 * z, "wall");   // y = 5, x 5..10
  add_quad(mesh, {5, 5, 0}, 3 * z, 5 * y, "wall");   // x = 5, y 5..10
  add_quad(mesh, {0, 10, 0}, 5 * x, 3 * z, "wall");  // y = 10
  return mesh;
}

// A 6 x 5 x 3 room with a thick wall across it (x 2.9 to 3.1, a 1 m gap at
// y 4..5) and a closed 1.2 x 1.2 x 2 cabinet at [4, 5.2] x [1, 2.2].
inline TriangleMesh room_with_solids() {
  TriangleMesh mesh;
  add_facing_box(mesh, {0, 0, 0}, {6, 5, 3}, true, "room");
  add_facing_box(mesh, {2.9, 0, 0}, {3.1, 4, 3}, false, "wall");
  add_facing_box(mesh, {4, 1, 0}, {5.2, 2.2, 2}, false, "cabinet");
  return mesh;
}

}  // namespace occlusion::testing
