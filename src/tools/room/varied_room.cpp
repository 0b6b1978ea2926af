#include "varied_room.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "floor_plan.hpp"
#include "palette.hpp"
#include "surface_sampler.hpp"

namespace occlusion::room {

namespace {

using Eigen::Vector3d;

// The layout's draws come from their own stream, apart from the points'
// (streams 1, 2, ... one per instance), so that the layout does not depend
// on the spacing.
constexpr std::uint64_t kLayoutStream = 0xFFFFFFFFull;
constexpr double kPi = 3.14159265358979323846;

struct Opening {
  std::size_t wall;
  double s0, s1, z0, z1;
  bool door;
  double angle;  // a door's leaf, radians open into the room
};

// The face of a box that rests against `wall`.
unsigned wall_face(const Wall& wall) {
  if (wall.inward.x() > 0.5) return kMinX;
  if (wall.inward.x() < -0.5) return kMaxX;
  return wall.inward.y() > 0.5 ? kMinY : kMaxY;
}

// The box from s0 to s1 along `wall`, d0 to d1 into the room, z0 to z1 high.
Box wall_box(const Wall& wall, double s0, double s1, double d0, double d1, double z0, double z1) {
  const Vector3d a = wall.at(s0) + d0 * wall.inward;
  const Vector3d b = wall.at(s1) + d1 * wall.inward;
  return {{std::min(a.x(), b.x()), std::min(a.y(), b.y()), z0},
          {std::max(a.x(), b.x()), std::max(a.y(), b.y()), z1}};
}

Rect footprint(const Box& box, double clearance) {
  return {box.lo.x() - clearance, box.lo.y() - clearance, box.hi.x() + clearance,
          box.hi.y() + clearance};
}

class Builder {
 public:
  Builder(std::uint64_t seed, double spacing, double sensor_noise)
      : layout_(seed, kLayoutStream), sampler_(seed, spacing, sensor_noise) {}

  VariedRoom build() {
    plan_ = random_floor_plan(layout_);
    const std::string& kind = plan_.kind;
    const bool open = kind == "openspace";
    const bool conference = kind == "conferenceRoom";
    const bool hallway = kind == "hallway";
    wall_colour_ = object_colour("wall", layout_);

    add_openings(count(1, hallway ? 3 : 2), count(hallway ? 0 : 1, open ? 5 : 3));
    add_beams(chance(0.5) ? count(1, 3) : 0);
    add_columns(count(0, open || conference ? 2 : 1));
    // Tables first among the furniture: they need the most room.
    const int tables = hallway ? 0 : (conference ? 1 : count(1, open ? 5 : 2));
    for (int t = 0; t < tables; ++t) add_table_with_chairs(conference);
    add_boards(count(conference ? 1 : 0, conference || open ? 2 : 1));
    add_bookcases(count(hallway ? 0 : 1, open ? 3 : 2));
    add_sofas(count(conference ? 0 : (kind == "lounge" ? 1 : 0), open ? 2 : 1));
    for (int c = count(hallway ? 1 : 0, 3); c > 0; --c) add_free_chair();
    for (int c = count(2, open ? 9 : 5); c > 0; --c) add_floor_clutter();
    for (std::size_t t = 0; t < table_tops_.size(); ++t) {
      for (int c = count(0, 3); c > 0; --c) add_table_clutter(t);
    }
    return sample();
  }

 private:
  double between(double lo, double hi) { return lo + (hi - lo) * layout_.uniform(); }
  int count(int lo, int hi) {
    return std::min(hi, lo + static_cast<int>(layout_.uniform() * (hi - lo + 1)));
  }
  bool chance(double p) { return layout_.uniform() < p; }

  Colour colour_of(const std::string& class_name) {
    // Beams and columns are often the walls' own paint.
    if ((class_name == "beam" || class_name == "column") && chance(0.5)) return wall_colour_;
    return object_colour(class_name, layout_);
  }

  void add(const std::string& class_name, std::vector<Box> boxes, std::vector<unsigned> skipped) {
    parts_.push_back({class_name, std::move(boxes), std::move(skipped), colour_of(class_name)});
  }

  bool free(const Rect& rect) const {
    if (!plan_.holds(rect)) return false;
    return std::none_of(occupied_.begin(), occupied_.end(),
                        [&](const Rect& other) { return other.overlaps(rect); });
  }

  // True when [s0, s1] on `wall` keeps `gap` from every opening there.
  bool clear_of_openings(std::size_t wall, double s0, double s1, double gap) const {
    return std::none_of(openings_.begin(), openings_.end(), [&](const Opening& o) {
      return o.wall == wall && s0 < o.s1 + gap && o.s0 - gap < s1;
    });
  }

  struct Spot {
    std::size_t wall;
    double s;
  };

  // A place `width` wide and `depth` deep against a wall, free of openings
  // and of what stands there already (with `clearance` around it).
  std::optional<Spot> wall_spot(double width, double depth, double clearance) {
    for (int attempt = 0; attempt < 40; ++attempt) {
      const std::size_t w = std::min(
          plan_.walls.size() - 1,
          static_cast<std::size_t>(layout_.uniform() * static_cast<double>(plan_.walls.size())));
      const Wall& wall = plan_.walls[w];
      if (wall.length < width + 0.4) continue;
      const double s = between(0.2, wall.length - width - 0.2);
      if (!clear_of_openings(w, s, s + width, 0.15)) continue;
      const Box box = wall_box(wall, s, s + width, 0.0, depth, 0, 1);
      Rect inner = footprint(box, -0.001);
      Rect outer = footprint(box, clearance);
      if (!plan_.holds(inner)) continue;
      if (std::any_of(occupied_.begin(), occupied_.end(),
                      [&](const Rect& other) { return other.overlaps(outer); }))
        continue;
      return Spot{w, s};
    }
    return std::nullopt;
  }

  // A free floor place for a w x d footprint with `clearance` around it.
  std::optional<Rect> floor_spot(double w, double d, double clearance) {
    const Rect& bounds = plan_.pieces[0];
    double max_x = bounds.x1;
    double max_y = bounds.y1;
    for (const Rect& piece : plan_.pieces) {
      max_x = std::max(max_x, piece.x1);
      max_y = std::max(max_y, piece.y1);
    }
    for (int attempt = 0; attempt < 60; ++attempt) {
      const double x = between(0.05 + clearance, max_x - w - clearance - 0.05);
      const double y = between(0.05 + clearance, max_y - d - clearance - 0.05);
      const Rect rect{x, y, x + w, y + d};
      const Rect around{x - clearance, y - clearance, x + w + clearance, y + d + clearance};
      if (rect.x0 < 0 || rect.y0 < 0 || !plan_.holds(rect)) continue;
      if (std::any_of(occupied_.begin(), occupied_.end(),
                      [&](const Rect& other) { return other.overlaps(around); }))
        continue;
      return rect;
    }
    return std::nullopt;
  }

  void add_openings(int doors, int windows) {
    for (int i = 0; i < doors + windows; ++i) {
      const bool door = i < doors;
      const double width = door ? between(0.8, 1.0) : between(0.8, 2.4);
      for (int attempt = 0; attempt < 40; ++attempt) {
        const std::size_t w = std::min(
            plan_.walls.size() - 1,
            static_cast<std::size_t>(layout_.uniform() * static_cast<double>(plan_.walls.size())));
        const Wall& wall = plan_.walls[w];
        if (wall.length < width + 0.5) continue;
        const double s = between(0.25, wall.length - width - 0.25);
        if (!clear_of_openings(w, s, s + width, 0.3)) continue;
        Opening opening{w, s, s + width, 0, 0, door, 0};
        if (door) {
          opening.z0 = -0.1;
          opening.z1 = std::min(plan_.height - 0.2, between(2.0, 2.15));
          opening.angle = between(0.0, 100.0) * kPi / 180.0;
          // The leaf's swing stays clear of furniture.
          occupied_.push_back(footprint(wall_box(wall, s, s + width, 0, width + 0.1, 0, 1), 0));
        } else {
          opening.z0 = between(0.8, 1.0);
          opening.z1 = std::min(plan_.height - 0.25, between(2.0, 2.5));
        }
        openings_.push_back(opening);
        break;
      }
    }
  }

  // Beams run under the ceiling from wall to wall across a piece of the
  // floor: across the short side of a rectangle; in an L, across either leg.
  void add_beams(int beams) {
    for (int b = 0; b < beams; ++b) {
      const double width = between(0.25, 0.4);
      const double depth = between(0.3, 0.5);
      const double top = plan_.height;
      const Rect& piece = plan_.pieces[plan_.pieces.size() == 2 && chance(0.5) ? 1 : 0];
      // Beams across y (at some x) need walls at both y ends: in an L's
      // lower leg only east of the notch.
      const bool across_y = plan_.pieces.size() == 2
                                ? &piece == &plan_.pieces[0]
                                : (piece.x1 - piece.x0) > (piece.y1 - piece.y0);
      if (across_y) {
        const double lo = plan_.pieces.size() == 2 ? plan_.pieces[1].x1 + 0.3 : piece.x0 + 0.5;
        if (piece.x1 - 0.5 - width <= lo) continue;
        const double x = between(lo, piece.x1 - 0.5 - width);
        add("beam", {{{x, piece.y0, top - depth}, {x + width, piece.y1, top}}},
            {kMaxZ | kMinY | kMaxY});
      } else {
        const double lo = plan_.pieces.size() == 2 ? piece.y0 + 0.3 : piece.y0 + 0.5;
        if (piece.y1 - 0.5 - width <= lo) continue;
        const double y = between(lo, piece.y1 - 0.5 - width);
        add("beam", {{{piece.x0, y, top - depth}, {piece.x1, y + width, top}}},
            {kMaxZ | kMinX | kMaxX});
      }
    }
  }

  void add_columns(int columns) {
    for (int c = 0; c < columns; ++c) {
      const double side = between(0.3, 0.6);
      if (plan_.kind == "openspace" && chance(0.5)) {
        const auto spot = floor_spot(side, side, 0.4);
        if (!spot) continue;
        occupied_.push_back(*spot);
        add("column", {{{spot->x0, spot->y0, 0}, {spot->x1, spot->y1, plan_.height}}},
            {kMinZ | kMaxZ});
        continue;
      }
      const auto spot = wall_spot(side, side, 0.1);
      if (!spot) continue;
      const Wall& wall = plan_.walls[spot->wall];
      const Box box = wall_box(wall, spot->s, spot->s + side, 0, side, 0, plan_.height);
      occupied_.push_back(footprint(box, 0));
      add("column", {box}, {kMinZ | kMaxZ | wall_face(wall)});
    }
  }

  void add_boards(int boards) {
    for (int b = 0; b < boards; ++b) {
      const double width = between(1.2, 3.0);
      const auto spot = wall_spot(width, 0.5, 0);  // half a metre kept free in front
      if (!spot) continue;
      const Wall& wall = plan_.walls[spot->wall];
      const double z0 = between(0.85, 1.0);
      const double z1 = std::min(plan_.height - 0.2, z0 + between(1.0, 1.3));
      occupied_.push_back(footprint(wall_box(wall, spot->s, spot->s + width, 0, 0.5, 0, 1), 0));
      add("board", {wall_box(wall, spot->s, spot->s + width, 0, 0.02, z0, z1)}, {wall_face(wall)});
    }
  }

  void add_bookcases(int bookcases) {
    for (int b = 0; b < bookcases; ++b) {
      const double width = between(0.8, 2.0);
      const double depth = between(0.3, 0.45);
      const double height = std::min(plan_.height - 0.3, between(1.6, 2.2));
      const auto spot = wall_spot(width, depth, 0.1);
      if (!spot) continue;
      const Wall& wall = plan_.walls[spot->wall];
      const Box box = wall_box(wall, spot->s, spot->s + width, 0, depth, 0, height);
      occupied_.push_back(footprint(box, 0));
      add("bookcase", {box}, {kMinZ | wall_face(wall)});
      if (chance(0.4)) {  // a box on top
        const double w = between(0.2, std::min(0.6, width - 0.1));
        const double s = spot->s + between(0.05, width - w - 0.05);
        add("clutter",
            {wall_box(wall, s, s + w, 0.02, depth - 0.02, height, height + between(0.1, 0.3))},
            {kMinZ});
      }
    }
  }

  void add_sofas(int sofas) {
    for (int f = 0; f < sofas; ++f) {
      const double width = between(1.6, 2.4);
      const double depth = between(0.85, 0.95);
      const auto spot = wall_spot(width, depth, 0.3);
      if (!spot) continue;
      const Wall& wall = plan_.walls[spot->wall];
      const double s = spot->s;
      const double seat = between(0.4, 0.45);
      const double arm = 0.15;
      const unsigned against = wall_face(wall);
      occupied_.push_back(footprint(wall_box(wall, s, s + width, 0, depth, 0, 1), 0));
      add("sofa",
          {wall_box(wall, s, s + width, 0, depth, 0, seat),
           wall_box(wall, s, s + width, 0, 0.2, seat, seat + between(0.4, 0.5)),
           wall_box(wall, s, s + arm, 0.2, depth, seat, seat + 0.2),
           wall_box(wall, s + width - arm, s + width, 0.2, depth, seat, seat + 0.2)},
          {kMinZ | against, kMinZ | against, kMinZ, kMinZ});
    }
  }

  // A chair centred at (x, y) whose sitter faces `facing` (a unit x or y axis).
  void add_chair(double x, double y, const Vector3d& facing) {
    const double half = between(0.2, 0.25);
    const double thin = 0.03;
    const double seat = between(0.42, 0.48);
    std::vector<Box> boxes{{{x - half, y - half, seat - 0.04}, {x + half, y + half, seat}}};
    for (const double dx : {-half, half - thin}) {
      for (const double dy : {-half, half - thin})
        boxes.push_back({{x + dx, y + dy, 0}, {x + dx + thin, y + dy + thin, seat - 0.04}});
    }
    // The backrest on the side away from where the sitter faces.
    const double top = seat + between(0.4, 0.55);
    Box back{{x - half, y - half, seat}, {x + half, y + half, top}};
    if (facing.x() > 0.5) back.hi.x() = back.lo.x() + thin;
    if (facing.x() < -0.5) back.lo.x() = back.hi.x() - thin;
    if (facing.y() > 0.5) back.hi.y() = back.lo.y() + thin;
    if (facing.y() < -0.5) back.lo.y() = back.hi.y() - thin;
    boxes.push_back(back);
    add("chair", boxes, {0, kMinZ, kMinZ, kMinZ, kMinZ, 0});
  }

  void add_table_with_chairs(bool conference) {
    const double length = conference ? between(2.8, 4.5) : between(1.2, 2.2);
    const double depth = conference ? between(1.1, 1.5) : between(0.7, 1.0);
    const bool along_x = chance(0.5);
    const double w = along_x ? length : depth;
    const double d = along_x ? depth : length;
    const auto spot = floor_spot(w, d, 0.75);
    if (!spot) return;
    occupied_.push_back({spot->x0 - 0.75, spot->y0 - 0.75, spot->x1 + 0.75, spot->y1 + 0.75});
    const double height = between(0.72, 0.78);
    const double leg = 0.05;
    std::vector<Box> table{{{spot->x0, spot->y0, height - 0.04}, {spot->x1, spot->y1, height}}};
    for (const double x : {spot->x0 + 0.05, spot->x1 - 0.05 - leg}) {
      for (const double y : {spot->y0 + 0.05, spot->y1 - 0.05 - leg})
        table.push_back({{x, y, 0}, {x + leg, y + leg, height - 0.04}});
    }
    add("table", table, {0, kMinZ, kMinZ, kMinZ, kMinZ});
    table_tops_.push_back({spot->x0, spot->y0, spot->x1, spot->y1});
    table_heights_.push_back(height);
    // Chairs along both long sides, about 0.65 m apart, some missing.
    const int per_side = std::max(1, static_cast<int>(length / 0.65));
    for (const double side : {-1.0, 1.0}) {
      for (int k = 0; k < per_side; ++k) {
        if (!chance(0.75)) continue;
        const double along = (k + 0.5) / per_side;
        const double gap = between(0.15, 0.25);  // the chair stays in the clearance
        const Rect chair_box = along_x ? Rect{spot->x0 + along * w - 0.25,
                                              side < 0 ? spot->y0 - gap - 0.5 : spot->y1 + gap,
                                              spot->x0 + along * w + 0.25,
                                              side < 0 ? spot->y0 - gap : spot->y1 + gap + 0.5}
                                       : Rect{side < 0 ? spot->x0 - gap - 0.5 : spot->x1 + gap,
                                              spot->y0 + along * d - 0.25,
                                              side < 0 ? spot->x0 - gap : spot->x1 + gap + 0.5,
                                              spot->y0 + along * d + 0.25};
        if (!plan_.holds(chair_box)) continue;
        const Vector3d facing = along_x ? Vector3d(0, -side, 0) : Vector3d(-side, 0, 0);
        add_chair((chair_box.x0 + chair_box.x1) / 2, (chair_box.y0 + chair_box.y1) / 2, facing);
      }
    }
  }

  void add_free_chair() {
    const auto spot = floor_spot(0.5, 0.5, 0.2);
    if (!spot) return;
    occupied_.push_back(*spot);
    const Vector3d facings[] = {Vector3d::UnitX(), -Vector3d::UnitX(), Vector3d::UnitY(),
                                -Vector3d::UnitY()};
    add_chair((spot->x0 + spot->x1) / 2, (spot->y0 + spot->y1) / 2,
              facings[std::min(3, static_cast<int>(layout_.uniform() * 4))]);
  }

  void add_floor_clutter() {
    const double w = between(0.2, 0.6);
    const double d = between(0.2, 0.6);
    const auto spot = floor_spot(w, d, 0.05);
    if (!spot) return;
    occupied_.push_back(*spot);
    add("clutter", {{{spot->x0, spot->y0, 0}, {spot->x1, spot->y1, between(0.2, 1.0)}}}, {kMinZ});
  }

  void add_table_clutter(std::size_t table) {
    const Rect& top = table_tops_[table];
    const double z = table_heights_[table];
    const double w = between(0.1, std::min(0.5, top.x1 - top.x0 - 0.1));
    const double d = between(0.1, std::min(0.5, top.y1 - top.y0 - 0.1));
    const double x = between(top.x0 + 0.05, top.x1 - w - 0.05);
    const double y = between(top.y0 + 0.05, top.y1 - d - 0.05);
    add("clutter", {{{x, y, z}, {x + w, y + d, z + between(0.05, 0.4)}}}, {kMinZ});
  }

  std::vector<Box> holes_on(std::size_t wall) const {
    std::vector<Box> holes;
    for (const Opening& o : openings_) {
      if (o.wall == wall)
        holes.push_back(wall_box(plan_.walls[wall], o.s0, o.s1, -0.1, 0.1, o.z0, o.z1));
    }
    return holes;
  }

  void window(const Opening& o, std::vector<Instance>& out) {
    constexpr double kFrame = 0.06;
    const Wall& wall = plan_.walls[o.wall];
    const Colour frame = colour_of("window");
    Instance& window = sampler_.start(out, "window");
    const Vector3d base = wall.at(o.s0) + 0.005 * wall.inward;
    const Vector3d across = (o.s1 - o.s0) * wall.along;
    const Vector3d side = kFrame * wall.along;
    const Vector3d bar(0, 0, kFrame);
    const Vector3d up(0, 0, o.z1 - o.z0 - 2 * kFrame);
    const Vector3d z0(0, 0, o.z0);
    sampler_.rectangle(window, base + z0, across, bar, frame, {});
    sampler_.rectangle(window, base + Vector3d(0, 0, o.z1 - kFrame), across, bar, frame, {});
    sampler_.rectangle(window, base + z0 + bar, side, up, frame, {});
    sampler_.rectangle(window, base + z0 + bar + across - side, side, up, frame, {});
  }

  void door(const Opening& o, std::vector<Instance>& out) {
    constexpr double kThickness = 0.04;
    const Wall& wall = plan_.walls[o.wall];
    const Colour leaf = colour_of("door");
    Instance& door = sampler_.start(out, "door");
    const double width = o.s1 - o.s0 - 0.02;
    const Vector3d hinge = wall.at(o.s0 + 0.01) + 0.01 * wall.inward + Vector3d(0, 0, 0.01);
    const Vector3d along =
        width * (std::cos(o.angle) * wall.along + std::sin(o.angle) * wall.inward);
    const Vector3d through =
        kThickness * (std::cos(o.angle) * wall.inward - std::sin(o.angle) * wall.along);
    const Vector3d up(0, 0, o.z1 - 0.03);
    sampler_.rectangle(door, hinge, along, up, leaf, {});
    sampler_.rectangle(door, hinge + through, up, along, leaf, {});
    sampler_.rectangle(door, hinge + along, through, up, leaf, {});  // free edge
    sampler_.rectangle(door, hinge + up, along, through, leaf, {});  // top edge
  }

  VariedRoom sample() {
    VariedRoom room;
    room.kind = plan_.kind;
    std::vector<Instance>& out = room.instances;
    sampler_.set_solids(parts_);
    const Colour ceiling = object_colour("ceiling", layout_);
    const Colour floor = object_colour("floor", layout_);
    const Vector3d up(0, 0, plan_.height);
    Instance& top = sampler_.start(out, "ceiling");
    for (const Rect& p : plan_.pieces) {
      sampler_.rectangle(top, Vector3d(p.x0, p.y0, 0) + up, {p.x1 - p.x0, 0, 0},
                         {0, p.y1 - p.y0, 0}, ceiling, {});
    }
    Instance& bottom = sampler_.start(out, "floor");
    for (const Rect& p : plan_.pieces) {
      sampler_.rectangle(bottom, {p.x0, p.y0, 0}, {0, p.y1 - p.y0, 0}, {p.x1 - p.x0, 0, 0}, floor,
                         {});
    }
    for (std::size_t w = 0; w < plan_.walls.size(); ++w) {
      const Wall& wall = plan_.walls[w];
      sampler_.rectangle(sampler_.start(out, "wall"), wall.start, wall.length * wall.along, up,
                         wall_colour_, holes_on(w));
    }
    for (const Opening& o : openings_) {
      if (o.door) {
        door(o, out);
      } else {
        window(o, out);
      }
      const Wall& wall = plan_.walls[o.wall];
      const double z0 = std::max(0.0, o.z0);
      room.openings.push_back(
          {wall.at(o.s0) + Vector3d(0, 0, z0), wall.at(o.s1) + Vector3d(0, 0, z0),
           wall.at(o.s1) + Vector3d(0, 0, o.z1), wall.at(o.s0) + Vector3d(0, 0, o.z1)});
    }
    sampler_.parts(out, parts_);
    return room;
  }

  Rng layout_;
  SurfaceSampler sampler_;
  FloorPlan plan_;
  Colour wall_colour_{};
  std::vector<Part> parts_;
  std::vector<Rect> occupied_;
  std::vector<Opening> openings_;
  std::vector<Rect> table_tops_;
  std::vector<double> table_heights_;
};

}  // namespace

VariedRoom varied_room(std::uint64_t seed, double spacing, double sensor_noise) {
  return Builder(seed, spacing, sensor_noise).build();
}

}  // namespace occlusion::room
