#include "occlusion/core/mesh.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/scenes.hpp"

namespace occlusion {
namespace {

TEST(Mesh, AreaBoundsAndValidate) {
  TriangleMesh mesh;
  testing::add_box(mesh, {0, 0, 0}, {2, 3, 4}, "box", 2);
  EXPECT_EQ(mesh.face_count(), 6u * 4u * 2u);
  double area = 0.0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) area += mesh.face_area(f);
  EXPECT_NEAR(area, 2 * (2 * 3 + 3 * 4 + 2 * 4), 1e-12);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  EXPECT_EQ(lo, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(hi, Eigen::Vector3d(2, 3, 4));
  EXPECT_NO_THROW(mesh.validate());
}

TEST(Mesh, ValidateRejectsBrokenMeshes) {
  TriangleMesh mesh;
  testing::add_quad(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "q");
  TriangleMesh bad_index = mesh;
  bad_index.faces[0][2] = 99;
  EXPECT_THROW(bad_index.validate(), std::invalid_argument);
  TriangleMesh bad_group = mesh;
  bad_group.face_group[1] = 5;
  EXPECT_THROW(bad_group.validate(), std::invalid_argument);
  TriangleMesh bad_sizes = mesh;
  bad_sizes.face_group.pop_back();
  EXPECT_THROW(bad_sizes.validate(), std::invalid_argument);
  TriangleMesh bad_vertex = mesh;
  bad_vertex.vertices[0].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(bad_vertex.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
