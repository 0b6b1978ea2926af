#include "room_generator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mesh_builder.hpp"
#include "occlusion/core/random.hpp"

namespace occlusion::bench {

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kWallClearance = 0.02;
constexpr double kPieceGap = 0.10;
// Pattern viewpoints stand at the room-box centre and halfway to two corners;
// keeping furniture this far from their vertical lines keeps them in free air.
constexpr double kViewpointClearance = 0.35;
constexpr int kPlacementAttempts = 200;
constexpr std::size_t kMaxTriangles = 50'000'000;

struct Rect {
  double x0, y0, x1, y1;

  bool overlaps(const Rect& o, double gap) const {
    return !(x1 + gap <= o.x0 || o.x1 + gap <= x0 || y1 + gap <= o.y0 || o.y1 + gap <= y0);
  }
  double distance_to(const Vector2d& p) const {
    const double dx = std::max({x0 - p.x(), 0.0, p.x() - x1});
    const double dy = std::max({y0 - p.y(), 0.0, p.y() - y1});
    return std::hypot(dx, dy);
  }
};

// Where a piece stands: its local xy turned by quarter turns, then moved to
// `origin`. Pieces are modelled facing local +y with their back on y = 0, so
// the same model serves every wall and every side of a table.
struct Frame {
  Vector2d origin{0.0, 0.0};
  int quarter_turns = 0;

  Vector2d map(const Vector2d& p) const {
    switch (quarter_turns & 3) {
      case 1:
        return origin + Vector2d(-p.y(), p.x());
      case 2:
        return origin + Vector2d(-p.x(), -p.y());
      case 3:
        return origin + Vector2d(p.y(), -p.x());
      default:
        return origin + p;
    }
  }
  // Quarter turns keep boxes axis-aligned, so mapping two corners suffices.
  void box(MeshBuilder& b, const Vector3d& lo, const Vector3d& hi) const {
    const Vector2d a = map(lo.head<2>());
    const Vector2d c = map(hi.head<2>());
    b.add_box(Vector3d(std::min(a.x(), c.x()), std::min(a.y(), c.y()), lo.z()),
              Vector3d(std::max(a.x(), c.x()), std::max(a.y(), c.y()), hi.z()));
  }
  Rect footprint(double width, double depth) const {
    const Vector2d a = map(Vector2d(0.0, 0.0));
    const Vector2d c = map(Vector2d(width, depth));
    return {std::min(a.x(), c.x()), std::min(a.y(), c.y()), std::max(a.x(), c.x()),
            std::max(a.y(), c.y())};
  }
};

struct Piece {
  std::string group;
  std::function<void(MeshBuilder&)> draw;
};

// Chooses every size and position once, from the seed; the pieces' draw
// functions then tessellate at whatever density the caller asks for.
class Planner {
 public:
  explicit Planner(std::uint64_t seed) : rng_(seed, kLayoutStream) {}

  std::vector<Piece> plan() {
    add_shell();
    for (int k = 0; k < 3; ++k) add_bookcase();
    add_sofa();
    for (int k = 0; k < 2; ++k) add_table_with_chairs();
    for (int k = 0; k < 2; ++k) add_lamp();
    for (int k = 0; k < 3; ++k) add_plant();
    return std::move(pieces_);
  }

 private:
  static constexpr std::uint64_t kLayoutStream = 0x726f6f6d;  // "room"

  double uniform(double lo, double hi) { return lo + (hi - lo) * rng_.uniform(); }
  int integer(int lo, int hi) {
    return std::min(hi, lo + static_cast<int>(rng_.uniform() * (hi - lo + 1)));
  }
  std::string name(const std::string& kind) { return kind + "_" + std::to_string(++count_[kind]); }

  bool is_free(const Rect& r) const {
    const Vector3d c = kRoomSize / 2.0;
    const std::array<Vector2d, 3> viewpoints{c.head<2>(), ((c + kRoomSize) / 2.0).head<2>(),
                                             (c / 2.0).head<2>()};
    for (const Vector2d& v : viewpoints) {
      if (r.distance_to(v) < kViewpointClearance) return false;
    }
    return std::none_of(taken_.begin(), taken_.end(),
                        [&](const Rect& t) { return t.overlaps(r, kPieceGap); });
  }

  // A free spot of width x depth with its back to a random wall.
  std::optional<Frame> place_against_wall(double width, double depth) {
    const double c = kWallClearance;
    const double sx = kRoomSize.x();
    const double sy = kRoomSize.y();
    for (int attempt = 0; attempt < kPlacementAttempts; ++attempt) {
      const int wall = integer(0, 3);
      const double along = wall < 2 ? sx : sy;
      const double pos = uniform(c, along - c - width);
      Frame f;
      switch (wall) {
        case 0:
          f = {Vector2d(pos, c), 0};
          break;  // south, facing +y
        case 1:
          f = {Vector2d(pos + width, sy - c), 2};
          break;  // north, facing -y
        case 2:
          f = {Vector2d(c, pos + width), 3};
          break;  // west, facing +x
        default:
          f = {Vector2d(sx - c, pos), 1};
          break;  // east, facing -x
      }
      const Rect r = f.footprint(width, depth);
      if (is_free(r)) {
        taken_.push_back(r);
        return f;
      }
    }
    return std::nullopt;
  }

  // A free axis-aligned spot of sx x sy anywhere on the floor.
  std::optional<Rect> place_anywhere(double sx, double sy) {
    const double c = kWallClearance;
    for (int attempt = 0; attempt < kPlacementAttempts; ++attempt) {
      const double x0 = uniform(c, kRoomSize.x() - c - sx);
      const double y0 = uniform(c, kRoomSize.y() - c - sy);
      const Rect r{x0, y0, x0 + sx, y0 + sy};
      if (is_free(r)) {
        taken_.push_back(r);
        return r;
      }
    }
    return std::nullopt;
  }

  void add_shell() {
    const double sx = kRoomSize.x();
    const double sy = kRoomSize.y();
    const double sz = kRoomSize.z();
    const Vector3d ex(sx, 0, 0), ey(0, sy, 0), ez(0, 0, sz), o(0, 0, 0);
    // Fronts face into the room.
    const std::array<std::pair<const char*, std::array<Vector3d, 3>>, 6> panels{{
        {"floor", {o, ex, ey}},
        {"ceiling", {ez, ey, ex}},
        {"wall_south", {o, ez, ex}},
        {"wall_north", {ey, ex, ez}},
        {"wall_west", {o, ey, ez}},
        {"wall_east", {ex, ez, ey}},
    }};
    for (const auto& [group, p] : panels) {
      pieces_.push_back({group, [p = p](MeshBuilder& b) { b.add_panel(p[0], p[1], p[2]); }});
    }
  }

  void add_bookcase() {
    const double w = uniform(0.8, 1.2);
    const double depth = 0.35;
    const double h = uniform(1.8, 2.2);
    const auto frame = place_against_wall(w, depth);
    if (!frame) return;
    const double t = 0.02, back = 0.01, plinth = 0.08;
    const int compartments = integer(4, 5);
    const double pitch = (h - t - plinth) / compartments;
    struct Book {
      Vector3d lo, hi;
    };
    std::vector<Book> books;
    for (int k = 0; k < compartments; ++k) {
      const double base = plinth + k * pitch;
      const double clear = pitch - t;
      for (double x = t + uniform(0.01, 0.1);;) {
        const double bw = uniform(0.1, 0.32);
        if (x + bw > w - t - 0.01) break;
        books.push_back(
            {Vector3d(x, back + 0.01, base), Vector3d(x + bw, back + 0.01 + uniform(0.18, 0.3),
                                                      base + clear * uniform(0.55, 0.9))});
        x += bw + uniform(0.03, 0.25);
      }
    }
    pieces_.push_back({name("bookcase"), [=, f = *frame](MeshBuilder& b) {
                         f.box(b, {0, 0, 0}, {t, depth, h});
                         f.box(b, {w - t, 0, 0}, {w, depth, h});
                         f.box(b, {t, 0, 0}, {w - t, back, h});
                         f.box(b, {t, back, 0}, {w - t, depth, plinth});
                         f.box(b, {t, back, h - t}, {w - t, depth, h});
                         for (int k = 1; k < compartments; ++k) {
                           const double top = plinth + k * pitch;
                           f.box(b, {t, back, top - t}, {w - t, depth, top});
                         }
                         for (const Book& book : books) f.box(b, book.lo, book.hi);
                       }});
  }

  void add_sofa() {
    const double w = uniform(1.8, 2.2);
    const double depth = 0.9;
    const auto frame = place_against_wall(w, depth);
    if (!frame) return;
    const double arm = 0.2, back = 0.22, seat = 0.42;
    pieces_.push_back(
        {name("sofa"), [=, f = *frame](MeshBuilder& b) {
           f.box(b, {0, 0, 0}, {arm, depth, 0.62});
           f.box(b, {w - arm, 0, 0}, {w, depth, 0.62});
           f.box(b, {arm, 0, 0}, {w - arm, back, 0.85});
           f.box(b, {arm, back, 0}, {w - arm, depth, seat});
           const double mid = w / 2.0;
           f.box(b, {arm + 0.02, back + 0.02, seat}, {mid - 0.01, depth - 0.02, 0.52});
           f.box(b, {mid + 0.01, back + 0.02, seat}, {w - arm - 0.02, depth - 0.02, 0.52});
         }});
  }

  void add_table_with_chairs() {
    double sx = uniform(1.2, 1.8);
    double sy = uniform(0.8, 1.0);
    if (integer(0, 1) == 1) std::swap(sx, sy);
    const double chair = 0.45, gap = 0.08, margin = chair + gap + 0.02;
    // The reserved footprint includes the chairs, so they never meet another piece.
    const auto area = place_anywhere(sx + 2 * margin, sy + 2 * margin);
    if (!area) return;
    const Rect top{area->x0 + margin, area->y0 + margin, area->x1 - margin, area->y1 - margin};
    const double h = uniform(0.72, 0.76);
    pieces_.push_back({name("table"), [=](MeshBuilder& b) {
                         b.add_box({top.x0, top.y0, h - 0.04}, {top.x1, top.y1, h});
                         const double leg = 0.06, inset = 0.05;
                         for (const double x : {top.x0 + inset, top.x1 - inset - leg}) {
                           for (const double y : {top.y0 + inset, top.y1 - inset - leg}) {
                             b.add_box({x, y, 0}, {x + leg, y + leg, h - 0.04});
                           }
                         }
                       }});
    add_vase(top, h);

    // Chairs face the table from each side; the long sides take two when there is room.
    std::vector<Frame> chairs;
    const auto seats_along = [](double length) { return length > 1.4 ? 2 : 1; };
    const int nx = seats_along(sx);
    for (int i = 0; i < nx; ++i) {
      const double x = top.x0 + sx * (i + 0.5) / nx;
      chairs.push_back({Vector2d(x - chair / 2, top.y0 - gap - chair), 0});
      chairs.push_back({Vector2d(x + chair / 2, top.y1 + gap + chair), 2});
    }
    const int ny = seats_along(sy);
    for (int i = 0; i < ny; ++i) {
      const double y = top.y0 + sy * (i + 0.5) / ny;
      chairs.push_back({Vector2d(top.x0 - gap - chair, y + chair / 2), 3});
      chairs.push_back({Vector2d(top.x1 + gap + chair, y - chair / 2), 1});
    }
    for (const Frame& f : chairs) {
      if (rng_.uniform() < 0.2) continue;
      const double seat = uniform(0.42, 0.46);
      pieces_.push_back({name("chair"), [=](MeshBuilder& b) {
                           const double leg = 0.035, inset = 0.02;
                           for (const double x : {inset, chair - inset - leg}) {
                             for (const double y : {inset, chair - inset - leg}) {
                               f.box(b, {x, y, 0}, {x + leg, y + leg, seat});
                             }
                           }
                           f.box(b, {0, 0, seat}, {chair, chair, seat + 0.04});
                           f.box(b, {0, 0, seat + 0.04}, {chair, 0.04, 0.9});
                         }});
    }
  }

  void add_vase(const Rect& table, double table_height) {
    const double margin = 0.15;
    const Vector2d axis(uniform(table.x0 + margin, table.x1 - margin),
                        uniform(table.y0 + margin, table.y1 - margin));
    const double rb = uniform(0.05, 0.07);
    const double h = uniform(0.2, 0.35);
    const double z = table_height;
    // Closed bottom standing on the table top, open mouth.
    const std::vector<ProfilePoint> profile{
        {0.0, z}, {rb, z}, {1.5 * rb, z + 0.35 * h}, {0.7 * rb, z + 0.8 * h}, {0.9 * rb, z + h}};
    pieces_.push_back({name("vase"), [=](MeshBuilder& b) { b.add_lathe(axis, profile); }});
  }

  void add_lamp() {
    const double shade_bottom_r = 0.2;
    const auto spot = place_anywhere(2 * shade_bottom_r, 2 * shade_bottom_r);
    if (!spot) return;
    const Vector2d axis((spot->x0 + spot->x1) / 2, (spot->y0 + spot->y1) / 2);
    const double h = uniform(1.5, 1.75);
    const double bulb = 0.05;
    const double bulb_z = h - 0.15;
    pieces_.push_back(
        {name("lamp"), [=](MeshBuilder& b) {
           b.add_lathe(axis, {{0.0, 0.0}, {0.15, 0.0}, {0.15, 0.03}, {0.0, 0.03}});
           // The pole stops where the bulb starts so that no surfaces cross.
           b.add_lathe(axis,
                       {{0.0, 0.03}, {0.012, 0.03}, {0.012, bulb_z - bulb}, {0.0, bulb_z - bulb}});
           b.add_sphere({axis.x(), axis.y(), bulb_z}, bulb);
           b.add_lathe(axis, {{shade_bottom_r, h - 0.3}, {0.12, h}});
         }});
  }

  void add_plant() {
    const double r = uniform(0.25, 0.4);
    const auto spot = place_anywhere(2 * r, 2 * r);
    if (!spot) return;
    const Vector2d axis((spot->x0 + spot->x1) / 2, (spot->y0 + spot->y1) / 2);
    const double pot = 0.3;
    const double trunk_top = pot + uniform(0.25, 0.6);
    pieces_.push_back(
        {name("plant"), [=](MeshBuilder& b) {
           b.add_lathe(axis, {{0.0, 0.0}, {0.12, 0.0}, {0.17, pot}, {0.0, pot}});
           b.add_lathe(axis, {{0.0, pot}, {0.02, pot}, {0.02, trunk_top}, {0.0, trunk_top}});
           b.add_sphere({axis.x(), axis.y(), trunk_top + r}, r);
         }});
  }

  Rng rng_;
  std::vector<Rect> taken_;
  std::vector<Piece> pieces_;
  std::map<std::string, int> count_;
};

TriangleMesh tessellate(const std::vector<Piece>& pieces, double density) {
  MeshBuilder builder(density);
  for (const Piece& piece : pieces) {
    builder.begin_group(piece.group);
    piece.draw(builder);
  }
  return builder.take();
}

// The OBJ reader refuses zero-area faces; catch any here, where the cause is known.
void check_no_degenerate_faces(const TriangleMesh& mesh) {
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Vector3d& a = mesh.vertices[mesh.faces[f][0]];
    const Vector3d e1 = mesh.vertices[mesh.faces[f][1]] - a;
    const Vector3d e2 = mesh.vertices[mesh.faces[f][2]] - a;
    const double longest = std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()});
    if (!(e1.cross(e2).norm() > 1e-9 * longest)) {
      throw std::logic_error("generate_room: face " + std::to_string(f) + " of group " +
                             mesh.group_names[mesh.face_group[f]] + " is degenerate");
    }
  }
}

}  // namespace

GeneratedRoom generate_room(std::size_t target_triangles, std::uint64_t seed) {
  if (target_triangles > kMaxTriangles) {
    throw std::invalid_argument("generate_room: at most " + std::to_string(kMaxTriangles) +
                                " triangles");
  }
  const std::vector<Piece> pieces = Planner(seed).plan();
  const auto count = [&](double density) { return tessellate(pieces, density).faces.size(); };

  // The count only grows with the density (every division count is a ceiling),
  // so bisection finds the smallest density that reaches the target.
  double lo = 1e-3;
  double hi = lo;
  if (count(lo) < target_triangles) {
    hi = 1.0;
    while (count(hi) < target_triangles) {
      lo = hi;
      hi *= 2.0;
    }
    while (hi - lo > 1e-4 * hi) {
      const double mid = (lo + hi) / 2.0;
      if (count(mid) >= target_triangles) {
        hi = mid;
      } else {
        lo = mid;
      }
    }
  }
  GeneratedRoom room{tessellate(pieces, hi), hi};
  check_no_degenerate_faces(room.mesh);
  return room;
}

}  // namespace occlusion::bench
