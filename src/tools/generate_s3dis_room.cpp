// generate_s3dis_room OUT_DIR [--seed S] [--spacing METRES] [--name office_1]
//                     [--openings FILE]
//
// Writes a labelled synthetic office in the S3DIS layout, so that demos and
// tests have a room without downloading the dataset:
//   OUT_DIR/<name>/<name>.txt                     every point, x y z r g b
//   OUT_DIR/<name>/Annotations/<class>_<k>.txt    one file per object instance
// and, with --openings, the window and door outlines as a polygon file
// (io/polygon_file.hpp).
//
// The room is 6 x 5 x 3 m, z up, its inner corner at the origin. The north wall
// (y = 5) has a window hole, the west wall (x = 0) a door hole reaching the
// floor; no wall points are sampled inside either hole. The window is a frame
// around its hole, the door a leaf standing 30 degrees open into the room.
// Furniture is boxes: a table, four chairs, a bookcase against the east wall, a
// board on the south wall and four clutter objects. Every surface a scanner in
// the room could see is sampled on a jittered grid of `--spacing` metres (one
// point per cell, so the density is even without being a lattice), with 1 mm
// of noise along the normal. Surfaces hidden by contact (wall behind the
// board, floor under the bookcase, a leg's top under the seat) are left out.
// The output depends on the seed and spacing only.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "occlusion/core/random.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/polygon_file.hpp"

namespace {

using Eigen::Vector3d;
using occlusion::Rng;
using Colour = std::array<int, 3>;

constexpr double kRoomX = 6.0;
constexpr double kRoomY = 5.0;
constexpr double kRoomZ = 3.0;
constexpr double kNormalNoise = 0.001;   // metres, uniform either side of the surface
constexpr double kContactMargin = 0.01;  // a surface this close inside another box is hidden
constexpr int kColourJitter = 10;

struct Box {
  Vector3d lo, hi;
  bool contains(const Vector3d& p, double margin) const {
    return (p.array() > lo.array() - margin).all() && (p.array() < hi.array() + margin).all();
  }
};

// Axis-aligned box faces, to leave out those resting on the floor or a wall.
enum Face : unsigned { kMinX = 1, kMaxX = 2, kMinY = 4, kMaxY = 8, kMinZ = 16, kMaxZ = 32 };

struct Point {
  Vector3d position;
  Colour colour;
};

struct Instance {
  std::string class_name;
  std::vector<Point> points;
};

struct Options {
  std::string out_dir;
  std::uint64_t seed = 0;
  double spacing = 0.02;
  std::string name = "office_1";
  std::string openings;
};

class RoomBuilder {
 public:
  explicit RoomBuilder(const Options& options) : options_(options) {}

  std::vector<Instance> build() {
    add_furniture_boxes();
    add_room_surfaces();
    add_window();
    add_door();
    add_furniture();
    return std::move(instances_);
  }

  static std::vector<std::vector<Vector3d>> openings() {
    return {{{kWindow.lo.x(), kRoomY, kWindow.lo.z()},
             {kWindow.hi.x(), kRoomY, kWindow.lo.z()},
             {kWindow.hi.x(), kRoomY, kWindow.hi.z()},
             {kWindow.lo.x(), kRoomY, kWindow.hi.z()}},
            {{0, kDoor.lo.y(), 0},
             {0, kDoor.hi.y(), 0},
             {0, kDoor.hi.y(), kDoor.hi.z()},
             {0, kDoor.lo.y(), kDoor.hi.z()}}};
  }

 private:
  // The holes, as boxes straddling their wall.
  static inline const Box kWindow{{2.0, kRoomY - 0.1, 0.9}, {3.6, kRoomY + 0.1, 2.2}};
  static inline const Box kDoor{{-0.1, 0.6, -0.1}, {0.1, 1.5, 2.1}};

  struct Part {
    std::string class_name;
    std::vector<Box> boxes;
    std::vector<unsigned> skipped_faces;  // per box
    Colour colour;
  };

  Instance& start(const std::string& class_name) {
    instances_.push_back({class_name, {}});
    // One stream per instance: changing one object leaves the others' points alone.
    rng_ = Rng(options_.seed, instances_.size());
    return instances_.back();
  }

  Colour jittered(const Colour& base) {
    Colour colour;
    for (int c = 0; c < 3; ++c) {
      const int offset =
          static_cast<int>(std::floor(rng_.uniform() * (2 * kColourJitter + 1))) - kColourJitter;
      colour[c] = std::clamp(base[c] + offset, 0, 255);
    }
    return colour;
  }

  // Samples the parallelogram origin + a u + b v (a, b in [0, 1]), one point per
  // grid cell, leaving out points inside `holes` or hidden by another box.
  void sample_rectangle(Instance& instance, const Vector3d& origin, const Vector3d& u,
                        const Vector3d& v, const Colour& colour, const std::vector<Box>& holes,
                        const Box* own_box) {
    const Vector3d normal = u.cross(v).normalized();
    const int cells_u = std::max(1, static_cast<int>(std::lround(u.norm() / options_.spacing)));
    const int cells_v = std::max(1, static_cast<int>(std::lround(v.norm() / options_.spacing)));
    for (int i = 0; i < cells_u; ++i) {
      for (int j = 0; j < cells_v; ++j) {
        const double a = (i + rng_.uniform()) / cells_u;
        const double b = (j + rng_.uniform()) / cells_v;
        const double noise = (2 * rng_.uniform() - 1) * kNormalNoise;
        const Vector3d surface = origin + a * u + b * v;
        const Colour point_colour = jittered(colour);
        if (hidden(surface, holes, own_box)) continue;
        instance.points.push_back({surface + noise * normal, point_colour});
      }
    }
  }

  bool hidden(const Vector3d& p, const std::vector<Box>& holes, const Box* own_box) const {
    for (const Box& hole : holes) {
      if (hole.contains(p, 0)) return true;
    }
    for (const Box& solid : solids_) {
      if (&solid != own_box && solid.contains(p, kContactMargin)) return true;
    }
    return false;
  }

  void sample_box(Instance& instance, const Box& box, unsigned skipped, const Colour& colour) {
    const Vector3d size = box.hi - box.lo;
    const Vector3d ex(size.x(), 0, 0);
    const Vector3d ey(0, size.y(), 0);
    const Vector3d ez(0, 0, size.z());
    const Vector3d& lo = box.lo;
    if (!(skipped & kMinX)) sample_rectangle(instance, lo, ez, ey, colour, {}, &box);
    if (!(skipped & kMaxX)) sample_rectangle(instance, lo + ex, ey, ez, colour, {}, &box);
    if (!(skipped & kMinY)) sample_rectangle(instance, lo, ex, ez, colour, {}, &box);
    if (!(skipped & kMaxY)) sample_rectangle(instance, lo + ey, ez, ex, colour, {}, &box);
    if (!(skipped & kMinZ)) sample_rectangle(instance, lo, ey, ex, colour, {}, &box);
    if (!(skipped & kMaxZ)) sample_rectangle(instance, lo + ez, ex, ey, colour, {}, &box);
  }

  void add_room_surfaces() {
    const Vector3d x(kRoomX, 0, 0);
    const Vector3d y(0, kRoomY, 0);
    const Vector3d z(0, 0, kRoomZ);
    const Colour ceiling{232, 232, 226};
    const Colour floor{128, 112, 96};
    const Colour wall{206, 200, 188};
    sample_rectangle(start("ceiling"), z, x, y, ceiling, {}, nullptr);
    sample_rectangle(start("floor"), Vector3d::Zero(), y, x, floor, {}, nullptr);
    sample_rectangle(start("wall"), Vector3d::Zero(), x, z, wall, {}, nullptr);       // south
    sample_rectangle(start("wall"), x, y, z, wall, {}, nullptr);                      // east
    sample_rectangle(start("wall"), y, z, x, wall, {kWindow}, nullptr);               // north
    sample_rectangle(start("wall"), Vector3d::Zero(), z, y, wall, {kDoor}, nullptr);  // west
  }

  // A 6 cm frame just inside the hole, in the wall plane: the glass itself
  // returns almost nothing to a scanner, so the opening stays open.
  void add_window() {
    constexpr double kFrame = 0.06;
    Instance& window = start("window");
    const Colour frame{238, 238, 236};
    const double x0 = kWindow.lo.x();
    const double x1 = kWindow.hi.x();
    const double z0 = kWindow.lo.z();
    const double z1 = kWindow.hi.z();
    const double y = kRoomY - 0.005;
    const Vector3d across(x1 - x0, 0, 0);
    const Vector3d up(0, 0, z1 - z0 - 2 * kFrame);
    sample_rectangle(window, {x0, y, z0}, across, {0, 0, kFrame}, frame, {}, nullptr);
    sample_rectangle(window, {x0, y, z1 - kFrame}, across, {0, 0, kFrame}, frame, {}, nullptr);
    sample_rectangle(window, {x0, y, z0 + kFrame}, {kFrame, 0, 0}, up, frame, {}, nullptr);
    sample_rectangle(window, {x1 - kFrame, y, z0 + kFrame}, {kFrame, 0, 0}, up, frame, {}, nullptr);
  }

  // The leaf is hinged at the hole's south edge and swung 30 degrees into the
  // room, so part of the doorway is open and part is hidden behind the leaf.
  void add_door() {
    constexpr double kOpenAngle = 30.0 * 3.14159265358979323846 / 180.0;
    constexpr double kThickness = 0.04;
    constexpr double kHeight = 2.08;
    Instance& door = start("door");
    const Colour leaf{148, 98, 58};
    const double width = kDoor.hi.y() - kDoor.lo.y() - 0.02;
    const Vector3d hinge(0.0, kDoor.lo.y() + 0.01, 0.01);
    const Vector3d along = width * Vector3d(std::sin(kOpenAngle), std::cos(kOpenAngle), 0);
    const Vector3d through = kThickness * Vector3d(std::cos(kOpenAngle), -std::sin(kOpenAngle), 0);
    const Vector3d up(0, 0, kHeight);
    sample_rectangle(door, hinge, along, up, leaf, {}, nullptr);
    sample_rectangle(door, hinge + through, up, along, leaf, {}, nullptr);
    sample_rectangle(door, hinge + along, through, up, leaf, {}, nullptr);  // free edge
    sample_rectangle(door, hinge + up, along, through, leaf, {}, nullptr);  // top edge
  }

  void add_part(const std::string& class_name, std::vector<Box> boxes,
                std::vector<unsigned> skipped, const Colour& colour) {
    parts_.push_back({class_name, boxes, skipped, colour});
  }

  // Registered first, so that every surface knows which boxes hide it.
  void add_furniture_boxes() {
    const double leg = 0.05;
    // Table, 1.6 x 0.8 m, top 0.75 m high.
    const Box top{{2.2, 1.9, 0.71}, {3.8, 2.7, 0.75}};
    std::vector<Box> table{top};
    for (const double x : {2.25, 3.75 - leg}) {
      for (const double y : {1.95, 2.65 - leg})
        table.push_back({{x, y, 0}, {x + leg, y + leg, 0.71}});
    }
    add_part("table", table, {0, kMinZ, kMinZ, kMinZ, kMinZ}, {178, 138, 88});

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
      add_part("chair", boxes, {0, kMinZ, kMinZ, kMinZ, kMinZ, 0}, {58, 60, 72});
    }

    add_part("bookcase", {{{kRoomX - 0.38, 2.8, 0}, {kRoomX, 4.0, 2.0}}}, {kMaxX | kMinZ},
             {118, 80, 50});
    add_part("board", {{{1.8, 0, 0.9}, {3.8, 0.02, 2.1}}}, {kMinY}, {248, 248, 246});

    add_part("clutter", {{{2.5, 2.3, 0.75}, {2.95, 2.5, 1.08}}}, {kMinZ}, {38, 38, 42});  // monitor
    add_part("clutter", {{{0.35, 4.25, 0}, {0.65, 4.55, 0.4}}}, {kMinZ}, {70, 120, 170});  // bin
    add_part("clutter", {{{5.7, 3.0, 2.0}, {5.95, 3.45, 2.24}}}, {kMinZ}, {196, 70, 60});  // box
    add_part("clutter", {{{5.3, 0.3, 0}, {5.75, 0.75, 0.62}}}, {kMinZ}, {84, 140, 62});    // plant
    for (const Part& part : parts_)
      solids_.insert(solids_.end(), part.boxes.begin(), part.boxes.end());
  }

  void add_furniture() {
    std::size_t solid = 0;
    for (const Part& part : parts_) {
      Instance& instance = start(part.class_name);
      for (std::size_t b = 0; b < part.boxes.size(); ++b, ++solid) {
        const unsigned skipped = b < part.skipped_faces.size() ? part.skipped_faces[b] : 0;
        sample_box(instance, solids_[solid], skipped, part.colour);
      }
    }
  }

  const Options& options_;
  Rng rng_{0};
  std::vector<Part> parts_;
  std::vector<Box> solids_;  // every furniture box, in part order
  std::vector<Instance> instances_;
};

void append_line(std::string& text, const Point& point) {
  char line[96];
  const int length = std::snprintf(line, sizeof line, "%.6f %.6f %.6f %d %d %d\n",
                                   point.position.x(), point.position.y(), point.position.z(),
                                   point.colour[0], point.colour[1], point.colour[2]);
  text.append(line, static_cast<std::size_t>(length));
}

void write_text(const std::string& path, const std::string& text) {
  occlusion::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

std::size_t write_room(const Options& options, const std::vector<Instance>& instances) {
  namespace fs = std::filesystem;
  const fs::path room = fs::path(options.out_dir) / options.name;
  occlusion::ensure_directory((room / "Annotations").string());
  std::string all;
  std::size_t points = 0;
  std::vector<std::pair<std::string, int>> counters;
  for (const Instance& instance : instances) {
    int number = 1;
    for (auto& [name, count] : counters) {
      if (name == instance.class_name) number = ++count;
    }
    if (number == 1) counters.emplace_back(instance.class_name, 1);
    std::string text;
    for (const Point& point : instance.points) append_line(text, point);
    write_text(
        (room / "Annotations" / (instance.class_name + "_" + std::to_string(number) + ".txt"))
            .string(),
        text);
    all += text;
    points += instance.points.size();
  }
  write_text((room / (options.name + ".txt")).string(), all);
  return points;
}

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "generate_s3dis_room: " << problem << "\n"
            << "usage: generate_s3dis_room OUT_DIR [--seed S] [--spacing METRES] "
               "[--name office_1] [--openings FILE]\n";
  std::exit(2);
}

// std::stod and friends stop at the first bad character; "0.05cm" is an error here.
template <class Convert>
auto whole_text_number(const std::string& text, Convert convert) {
  std::size_t end = 0;
  const auto value = convert(text, &end);
  if (end != text.size()) throw std::invalid_argument(text);
  return value;
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(arg + " needs a value");
      return argv[++i];
    };
    try {
      if (arg == "--seed") {
        options.seed = whole_text_number(
            value(), [](const std::string& t, std::size_t* end) { return std::stoull(t, end); });
      } else if (arg == "--spacing") {
        options.spacing = whole_text_number(
            value(), [](const std::string& t, std::size_t* end) { return std::stod(t, end); });
      } else if (arg == "--name") {
        options.name = value();
      } else if (arg == "--openings") {
        options.openings = value();
      } else if (!arg.empty() && arg[0] == '-') {
        usage("unknown option " + arg);
      } else if (options.out_dir.empty()) {
        options.out_dir = arg;
      } else {
        usage("more than one OUT_DIR");
      }
    } catch (const std::logic_error&) {
      usage(arg + " needs a number");
    }
  }
  if (options.out_dir.empty()) usage("OUT_DIR is missing");
  // Below 5 mm the room has tens of millions of points, more than any scan.
  if (!(options.spacing >= 0.005 && options.spacing <= 1.0))
    usage("--spacing must be in [0.005, 1]");
  if (options.name.empty() || options.name.find('/') != std::string::npos ||
      options.name[0] == '.') {
    usage("--name must be a plain folder name");
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    const std::vector<Instance> instances = RoomBuilder(options).build();
    const std::size_t points = write_room(options, instances);
    if (!options.openings.empty()) {
      occlusion::write_polygons(options.openings, RoomBuilder::openings());
    }
    std::cerr << "generate_s3dis_room: " << points << " points in " << instances.size()
              << " instances written to " << options.out_dir << "/" << options.name << "\n";
  } catch (const std::exception& error) {
    std::cerr << "generate_s3dis_room: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
