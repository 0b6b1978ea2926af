// The real Cornell box file (files/cornell_box, public domain): 72 vertices,
// 18 quads written with negative indices, CRLF line endings, tabs, and `g`
// statements that come AFTER the faces they name in the comments. Counted from
// the file: floor, ceiling, backWall, rightWall and leftWall each get their own
// quad; the short box's 6 quads precede `g shortBox`, so they are in leftWall;
// the tall box's 6 quads precede `g tallBox`, so they are in shortBox; tallBox
// has no faces; the light quad is in light.

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "occlusion/io/obj_reader.hpp"

namespace occlusion {
namespace {

const std::string kCornellBox =
    std::string(OCCLUSION_SOURCE_DIR) + "/files/cornell_box/CornellBox-Original.obj";

TEST(CornellBox, LoadsAllQuadsAsTriangles) {
  const TriangleMesh mesh = read_obj(kCornellBox);
  EXPECT_EQ(mesh.vertices.size(), 72u);
  EXPECT_EQ(mesh.faces.size(), 36u);
  EXPECT_NO_THROW(mesh.validate());
}

TEST(CornellBox, GroupsFollowOBJRulesNotComments) {
  const TriangleMesh mesh = read_obj(kCornellBox);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"floor", "ceiling", "backWall", "rightWall",
                                                        "leftWall", "shortBox", "light"}));
  std::map<std::string, int> triangles_per_group;
  for (const auto group : mesh.face_group) ++triangles_per_group[mesh.group_names.at(group)];
  EXPECT_EQ(triangles_per_group, (std::map<std::string, int>{{"floor", 2},
                                                             {"ceiling", 2},
                                                             {"backWall", 2},
                                                             {"rightWall", 2},
                                                             {"leftWall", 14},
                                                             {"shortBox", 12},
                                                             {"light", 2}}));
}

TEST(CornellBox, NegativeIndicesPickTheRightVertices) {
  const TriangleMesh mesh = read_obj(kCornellBox);
  // The first quad is the floor: its first vertex is the file's first `v`.
  EXPECT_EQ(mesh.faces.front()[0], 0u);
  EXPECT_EQ(mesh.vertices[0], Eigen::Vector3d(-1.01, 0.00, 0.99));
  // The light is the last quad, over the last four vertices, 0.47 x 0.38 at y = 1.98.
  const std::size_t last = mesh.faces.size() - 1;
  EXPECT_EQ(mesh.faces[last - 1], (std::array<std::uint32_t, 3>{68, 69, 70}));
  EXPECT_EQ(mesh.faces[last], (std::array<std::uint32_t, 3>{68, 70, 71}));
  EXPECT_NEAR(mesh.face_area(last - 1) + mesh.face_area(last), 0.47 * 0.38, 1e-12);
  for (const auto index : mesh.faces[last]) EXPECT_DOUBLE_EQ(mesh.vertices[index].y(), 1.98);
}

}  // namespace
}  // namespace occlusion
