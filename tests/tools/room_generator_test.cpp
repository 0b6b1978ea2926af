// The room generator (src/tools/room, generate_s3dis_room): the office as it
// always was, rooms that vary with the seed, every S3DIS class across a small
// dataset, the same bytes for the same seed, and output the readers take.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/scratch_directory.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "room/office_room.hpp"
#include "room/room_writer.hpp"
#include "room/varied_room.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::ScratchDirectory;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kTool = GENERATE_S3DIS_ROOM_PATH;

const std::vector<std::string> kS3disClasses{"ceiling",  "floor", "wall",   "beam",  "column",
                                             "window",   "door",  "table",  "chair", "sofa",
                                             "bookcase", "board", "clutter"};

Eigen::AlignedBox3d bounds(const std::vector<room::Instance>& instances) {
  Eigen::AlignedBox3d box;
  for (const auto& instance : instances) {
    for (const auto& point : instance.points) box.extend(point.position);
  }
  return box;
}

int run(const std::string& arguments) {
  return std::system((kTool + " " + arguments + " 2>/dev/null").c_str());
}

// Every file under `dir`, by its path relative to it, with its bytes.
std::map<std::string, std::string> files(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file())
      out[fs::relative(entry.path(), dir).string()] = read_bytes(entry.path().string());
  }
  return out;
}

TEST(RoomGenerator, TheOfficeIsTheCommittedOneToTheByte) {
  // files/s3dis_synthetic was made by the generator before the varied rooms
  // existed (its README gives the command): the office must not have moved.
  const ScratchDirectory dir;
  const std::string committed = kSource + "/files/s3dis_synthetic";
  ASSERT_EQ(run(dir.file("Area_1") + " --spacing 0.065 --openings " + dir.file("openings.txt")), 0);
  EXPECT_EQ(files(dir.file("Area_1")), files(committed + "/Area_1"));
  EXPECT_EQ(read_bytes(dir.file("openings.txt")), read_bytes(committed + "/openings.txt"));
}

TEST(RoomGenerator, RoomsFromDifferentSeedsDifferInSizeAndShape) {
  std::set<std::string> kinds;
  std::vector<Eigen::Vector3d> sizes;
  std::size_t l_shapes = 0;
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    const room::VariedRoom made = room::varied_room(seed, 0.2, 0.0);
    kinds.insert(made.kind);
    const Eigen::Vector3d size = bounds(made.instances).sizes();
    // Sizes as the floor plans draw them (2 mm of noise and jitter aside).
    EXPECT_GE(size.x(), 2.9) << seed;
    EXPECT_LE(size.x(), 14.1) << seed;
    EXPECT_GE(size.y(), 1.5) << seed;
    EXPECT_GE(size.z(), 2.5) << seed;
    EXPECT_LE(size.z(), 4.1) << seed;
    for (const Eigen::Vector3d& other : sizes) EXPECT_GT((size - other).norm(), 0.01) << seed;
    sizes.push_back(size);
    if (made.kind == "lounge") {
      ++l_shapes;
      // An L: no floor point in the bounding box's north-east corner.
      std::size_t walls = 0;
      for (const auto& instance : made.instances) walls += instance.class_name == "wall" ? 1 : 0;
      EXPECT_EQ(walls, 6u);
      const Eigen::AlignedBox3d box = bounds(made.instances);
      const Eigen::Vector3d corner = box.max() - Eigen::Vector3d(0.2, 0.2, 0);
      for (const auto& instance : made.instances) {
        if (instance.class_name != "floor") continue;
        for (const auto& point : instance.points) {
          EXPECT_FALSE(point.position.x() > corner.x() && point.position.y() > corner.y())
              << "seed " << seed << ": a floor point in the L's missing corner";
        }
      }
    }
  }
  EXPECT_GE(kinds.size(), 4u);
  EXPECT_GE(l_shapes, 1u);
}

TEST(RoomGenerator, EveryS3disClassAppearsAcrossASmallDataset) {
  std::map<std::string, std::size_t> points;
  for (std::uint64_t k = 0; k < 12; ++k) {
    const std::uint64_t seed = Rng(1, k).next();  // as --dataset --seed 1 draws them
    for (const auto& instance : room::varied_room(seed, 0.1, 0.0).instances)
      points[instance.class_name] += instance.points.size();
  }
  for (const std::string& name : kS3disClasses) EXPECT_GT(points[name], 0u) << name;
  EXPECT_EQ(points.size(), kS3disClasses.size());  // no other class
}

TEST(RoomGenerator, ColoursDoNotNameTheClass) {
  // A colour shared by several classes: over a dataset, the nearest class
  // mean colour calls well under half of the points right for most classes
  // (a palette per class would call nearly all of them right).
  std::map<std::string, Eigen::Vector3d> sum;
  std::map<std::string, double> count;
  std::vector<std::pair<std::string, Eigen::Vector3d>> samples;
  for (std::uint64_t k = 0; k < 12; ++k) {
    for (const auto& instance : room::varied_room(Rng(1, k).next(), 0.2, 0.0).instances) {
      for (const auto& point : instance.points) {
        const Eigen::Vector3d c(point.colour[0], point.colour[1], point.colour[2]);
        sum[instance.class_name] += c;
        count[instance.class_name] += 1;
        samples.emplace_back(instance.class_name, c);
      }
    }
  }
  std::size_t right = 0;
  for (const auto& [name, colour] : samples) {
    std::string nearest;
    double best = 1e300;
    for (const auto& [other, total] : sum) {
      const double d = (colour - total / count[other]).squaredNorm();
      if (d < best) best = d, nearest = other;
    }
    right += nearest == name ? 1 : 0;
  }
  EXPECT_LT(static_cast<double>(right) / static_cast<double>(samples.size()), 0.5);
}

TEST(RoomGenerator, SensorNoiseSpreadsTheFloorByItsStandardDeviation) {
  for (const double sigma : {0.0, 0.01}) {
    const room::VariedRoom made = room::varied_room(5, 0.1, sigma);
    double sum = 0, squares = 0, n = 0;
    for (const auto& instance : made.instances) {
      if (instance.class_name != "floor") continue;
      for (const auto& point : instance.points) {
        sum += point.position.z();
        squares += point.position.z() * point.position.z();
        n += 1;
      }
    }
    ASSERT_GT(n, 100);
    const double spread = std::sqrt(squares / n - (sum / n) * (sum / n));
    // Without sensor noise only the 1 mm uniform normal noise: sd 0.58 mm.
    if (sigma == 0) {
      EXPECT_LT(spread, 0.001);
    } else {
      EXPECT_NEAR(spread, std::sqrt(sigma * sigma + 0.001 * 0.001 / 3), 0.1 * sigma);
    }
  }
}

TEST(RoomGenerator, OneCommandMakesADatasetTheReadersTakeTheSameForTheSameSeed) {
  const ScratchDirectory dir;
  ASSERT_EQ(run("--dataset " + dir.file("a") + " --rooms 3 --seed 4 --spacing 0.1"), 0);
  ASSERT_EQ(run("--dataset " + dir.file("b") + " --rooms 3 --seed 4 --spacing 0.1"), 0);
  ASSERT_EQ(run("--dataset " + dir.file("c") + " --rooms 3 --seed 5 --spacing 0.1"), 0);
  const auto a = files(dir.file("a"));
  EXPECT_EQ(a, files(dir.file("b")));
  EXPECT_NE(a, files(dir.file("c")));
  // rooms.tsv: a header and a line per room; each room's seed remakes it alone.
  const std::string table = a.at("rooms.tsv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 4);
  std::vector<std::string> fields;  // the first room's: room, kind, seed, points
  std::string field;
  for (const char c : table.substr(table.find('\n') + 1)) {
    if (c == '\t' || c == '\n') {
      fields.push_back(field);
      field.clear();
      if (c == '\n') break;
    } else {
      field += c;
    }
  }
  ASSERT_EQ(fields.size(), 4u);
  const std::string& name = fields[0];
  const std::string& seed = fields[2];
  ASSERT_EQ(run(dir.file("one") + " --varied --seed " + seed + " --spacing 0.1 --name " + name), 0);
  EXPECT_EQ(read_bytes(dir.file("one/" + name + "/" + name + ".txt")),
            a.at("Area_1/" + name + "/" + name + ".txt"));

  // The S3DIS reader (as -recon and the study read a scene) takes every room.
  const PointCloud area = read_cloud(dir.file("a/Area_1"));
  std::size_t expected = 0;
  for (const auto& [path, bytes] : a) {
    if (path.find("/Annotations/") != std::string::npos)
      expected += static_cast<std::size_t>(std::count(bytes.begin(), bytes.end(), '\n'));
  }
  EXPECT_EQ(area.size(), expected);
  EXPECT_EQ(area.labels.size(), expected);
  for (const auto& [path, bytes] : a) {
    if (path.rfind("openings/", 0) == 0) {
      EXPECT_FALSE(bytes.empty()) << path;
    }
  }
}

// Whether p lies on the triangle, within `tolerance` of its plane.
bool on_triangle(const Eigen::Vector3d& p, const room::Triangle3d& t, double tolerance) {
  const Eigen::Vector3d e1 = t[1] - t[0], e2 = t[2] - t[0], d = p - t[0];
  const Eigen::Vector3d normal = e1.cross(e2).normalized();
  if (std::abs(d.dot(normal)) > tolerance) return false;
  // Barycentric coordinates of p's projection.
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double p1 = d.dot(e1), p2 = d.dot(e2);
  const double det = d11 * d22 - d12 * d12;
  const double b1 = (d22 * p1 - d12 * p2) / det, b2 = (d11 * p2 - d12 * p1) / det;
  const double slack = 1e-6;
  return b1 >= -slack && b2 >= -slack && b1 + b2 <= 1 + slack;
}

TEST(RoomGenerator, TheMeshHoldsEveryPointOnItsOwnInstanceAndLeavesTheOpeningsOpen) {
  for (const std::uint64_t seed : {3u, 8u}) {
    const room::VariedRoom made = room::varied_room(seed, 0.15, 0.0);
    ASSERT_FALSE(made.openings.empty()) << seed;
    for (const auto& instance : made.instances) {
      ASSERT_FALSE(instance.triangles.empty()) << instance.class_name;
      // Each point was sampled on one of its instance's surfaces, then moved
      // at most 1 mm along the normal.
      for (const auto& point : instance.points) {
        const bool on_surface =
            std::any_of(instance.triangles.begin(), instance.triangles.end(),
                        [&](const auto& t) { return on_triangle(point.position, t, 0.0011); });
        ASSERT_TRUE(on_surface) << seed << " " << instance.class_name << " point "
                                << point.position.transpose() << " is on no triangle of its own";
      }
    }
    // A ray through a door or window's middle meets no wall.
    for (const auto& opening : made.openings) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const auto& corner : opening) centre += corner;
      centre /= static_cast<double>(opening.size());
      for (const auto& instance : made.instances) {
        if (instance.class_name != "wall") continue;
        for (const auto& t : instance.triangles) {
          EXPECT_FALSE(on_triangle(centre, t, 0.05))
              << seed << ": a wall triangle covers the opening at " << centre.transpose();
        }
      }
    }
  }
  // The tool writes them as an OBJ with one group per instance, named as
  // its Annotations file; without --mesh, no OBJ.
  const ScratchDirectory dir;
  ASSERT_EQ(run(dir.file("with") + " --varied --seed 3 --spacing 0.2 --name r --mesh"), 0);
  ASSERT_EQ(run(dir.file("without") + " --varied --seed 3 --spacing 0.2 --name r"), 0);
  EXPECT_FALSE(fs::exists(dir.file("without/r/r.obj")));
  const std::string obj = read_bytes(dir.file("with/r/r.obj"));
  std::size_t groups = 0;
  for (const auto& entry : fs::directory_iterator(dir.file("with/r/Annotations"))) {
    const std::string group = "\ng " + entry.path().stem().string() + "\n";
    EXPECT_NE(obj.find(group), std::string::npos) << group;
    ++groups;
  }
  std::size_t group_lines = 0;
  for (std::size_t at = obj.find("\ng "); at != std::string::npos; at = obj.find("\ng ", at + 1))
    ++group_lines;
  EXPECT_EQ(group_lines, groups);  // one run of faces per instance
  EXPECT_GT(groups, 5u);
  // The points are those of a room made without --mesh, to the byte.
  EXPECT_EQ(read_bytes(dir.file("with/r/r.txt")), read_bytes(dir.file("without/r/r.txt")));
}

TEST(RoomGenerator, BadOptionsAreRefused) {
  const ScratchDirectory dir;
  EXPECT_NE(run("--dataset " + dir.file("x") + " --rooms 0"), 0);
  EXPECT_NE(run("--dataset " + dir.file("x") + " --rooms 2 --name office_1"), 0);
  EXPECT_NE(run(dir.file("x") + " --rooms 2"), 0);
  EXPECT_NE(run(dir.file("x") + " --noise -1"), 0);
  EXPECT_FALSE(fs::exists(dir.file("x")));
}

}  // namespace
}  // namespace occlusion
