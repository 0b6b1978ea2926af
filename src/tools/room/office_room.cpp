#include "office_room.hpp"

#include <cmath>
#include <string>

#include "surface_sampler.hpp"

namespace occlusion::room {

namespace {

using Eigen::Vector3d;

constexpr double kRoomX = 6.0;
constexpr double kRoomY = 5.0;
constexpr double kRoomZ = 3.0;

// The holes, as boxes straddling their wall.
const Box kWindow{{2.0, kRoomY - 0.1, 0.9}, {3.6, kRoomY + 0.1, 2.2}};
const Box kDoor{{-0.1, 0.6, -0.1}, {0.1, 1.5, 2.1}};

std::vector<Part> furniture() {
  std::vector<Part> parts;
  const double leg = 0.05;
  // Table, 1.6 x 0.8 m, top 0.75 m high.
  const Box top{{2.2, 1.9, 0.71}, {3.8, 2.7, 0.75}};
  std::vector<Box> table{top};
  for (const double x : {2.25, 3.75 - leg}) {
    for (const double y : {1.95, 2.65 - leg})
      table.push_back({{x, y, 0}, {x + leg, y + leg, 0.71}});
  }
  parts.push_back({"table", table, {0, kMinZ, kMinZ, kMinZ, kMinZ}, {178, 138, 88}});

  // Chairs: seat 0.44 m square at 0.45 m, backrest on the side away from the table.
  const struct {
    double x, y;
    bool back_south;
  } chairs[] = {{2.5, 1.35, true}, {3.5, 1.35, true}, {2.5, 3.25, false}, {3.5, 3.25, false}};
  for (const auto& chair : chairs) {
    const double half = 0.22;
    const double thin = 0.03;
    std::vector<Box> boxes{
        {{chair.x - half, chair.y - half, 0.43}, {chair.x + half, chair.y + half, 0.47}}};
    for (const double dx : {-half, half - thin}) {
      for (const double dy : {-half, half - thin}) {
        boxes.push_back(
            {{chair.x + dx, chair.y + dy, 0}, {chair.x + dx + thin, chair.y + dy + thin, 0.43}});
      }
    }
    const double back_y = chair.back_south ? chair.y - half : chair.y + half - thin;
    boxes.push_back({{chair.x - half, back_y, 0.47}, {chair.x + half, back_y + thin, 0.9}});
    parts.push_back({"chair", boxes, {0, kMinZ, kMinZ, kMinZ, kMinZ, 0}, {58, 60, 72}});
  }

  parts.push_back({"bookcase",
                   {{{kRoomX - 0.38, 2.8, 0}, {kRoomX, 4.0, 2.0}}},
                   {kMaxX | kMinZ},
                   {118, 80, 50}});
  parts.push_back({"board", {{{1.8, 0, 0.9}, {3.8, 0.02, 2.1}}}, {kMinY}, {248, 248, 246}});

  parts.push_back(
      {"clutter", {{{2.5, 2.3, 0.75}, {2.95, 2.5, 1.08}}}, {kMinZ}, {38, 38, 42}});  // monitor
  parts.push_back({"clutter", {{{0.35, 4.25, 0}, {0.65, 4.55, 0.4}}}, {kMinZ}, {70, 120, 170}});
  parts.push_back({"clutter", {{{5.7, 3.0, 2.0}, {5.95, 3.45, 2.24}}}, {kMinZ}, {196, 70, 60}});
  parts.push_back({"clutter", {{{5.3, 0.3, 0}, {5.75, 0.75, 0.62}}}, {kMinZ}, {84, 140, 62}});
  return parts;
}

void room_surfaces(SurfaceSampler& sampler, std::vector<Instance>& out) {
  const Vector3d x(kRoomX, 0, 0);
  const Vector3d y(0, kRoomY, 0);
  const Vector3d z(0, 0, kRoomZ);
  const Colour ceiling{232, 232, 226};
  const Colour floor{128, 112, 96};
  const Colour wall{206, 200, 188};
  sampler.rectangle(sampler.start(out, "ceiling"), z, x, y, ceiling, {});
  sampler.rectangle(sampler.start(out, "floor"), Vector3d::Zero(), y, x, floor, {});
  sampler.rectangle(sampler.start(out, "wall"), Vector3d::Zero(), x, z, wall, {});       // south
  sampler.rectangle(sampler.start(out, "wall"), x, y, z, wall, {});                      // east
  sampler.rectangle(sampler.start(out, "wall"), y, z, x, wall, {kWindow});               // north
  sampler.rectangle(sampler.start(out, "wall"), Vector3d::Zero(), z, y, wall, {kDoor});  // west
}

// A 6 cm frame just inside the hole, in the wall plane: the glass itself
// returns almost nothing to a scanner, so the opening stays open.
void window(SurfaceSampler& sampler, std::vector<Instance>& out) {
  constexpr double kFrame = 0.06;
  Instance& window = sampler.start(out, "window");
  const Colour frame{238, 238, 236};
  const double x0 = kWindow.lo.x();
  const double x1 = kWindow.hi.x();
  const double z0 = kWindow.lo.z();
  const double z1 = kWindow.hi.z();
  const double y = kRoomY - 0.005;
  const Vector3d across(x1 - x0, 0, 0);
  const Vector3d up(0, 0, z1 - z0 - 2 * kFrame);
  sampler.rectangle(window, {x0, y, z0}, across, {0, 0, kFrame}, frame, {});
  sampler.rectangle(window, {x0, y, z1 - kFrame}, across, {0, 0, kFrame}, frame, {});
  sampler.rectangle(window, {x0, y, z0 + kFrame}, {kFrame, 0, 0}, up, frame, {});
  sampler.rectangle(window, {x1 - kFrame, y, z0 + kFrame}, {kFrame, 0, 0}, up, frame, {});
}

// The leaf is hinged at the hole's south edge and swung 30 degrees into the
// room, so part of the doorway is open and part is hidden behind the leaf.
void door(SurfaceSampler& sampler, std::vector<Instance>& out) {
  constexpr double kOpenAngle = 30.0 * 3.14159265358979323846 / 180.0;
  constexpr double kThickness = 0.04;
  constexpr double kHeight = 2.08;
  Instance& door = sampler.start(out, "door");
  const Colour leaf{148, 98, 58};
  const double width = kDoor.hi.y() - kDoor.lo.y() - 0.02;
  const Vector3d hinge(0.0, kDoor.lo.y() + 0.01, 0.01);
  const Vector3d along = width * Vector3d(std::sin(kOpenAngle), std::cos(kOpenAngle), 0);
  const Vector3d through = kThickness * Vector3d(std::cos(kOpenAngle), -std::sin(kOpenAngle), 0);
  const Vector3d up(0, 0, kHeight);
  sampler.rectangle(door, hinge, along, up, leaf, {});
  sampler.rectangle(door, hinge + through, up, along, leaf, {});
  sampler.rectangle(door, hinge + along, through, up, leaf, {});  // free edge
  sampler.rectangle(door, hinge + up, along, through, leaf, {});  // top edge
}

}  // namespace

std::vector<Instance> office_room(std::uint64_t seed, double spacing, double sensor_noise) {
  SurfaceSampler sampler(seed, spacing, sensor_noise);
  const std::vector<Part> parts = furniture();
  sampler.set_solids(parts);
  std::vector<Instance> instances;
  room_surfaces(sampler, instances);
  window(sampler, instances);
  door(sampler, instances);
  sampler.parts(instances, parts);
  return instances;
}

std::vector<std::vector<Vector3d>> office_openings() {
  return {{{kWindow.lo.x(), kRoomY, kWindow.lo.z()},
           {kWindow.hi.x(), kRoomY, kWindow.lo.z()},
           {kWindow.hi.x(), kRoomY, kWindow.hi.z()},
           {kWindow.lo.x(), kRoomY, kWindow.hi.z()}},
          {{0, kDoor.lo.y(), 0},
           {0, kDoor.hi.y(), 0},
           {0, kDoor.hi.y(), kDoor.hi.z()},
           {0, kDoor.lo.y(), kDoor.hi.z()}}};
}

}  // namespace occlusion::room
