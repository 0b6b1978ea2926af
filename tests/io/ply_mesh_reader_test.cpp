#include <gtest/gtest.h>

#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "occlusion/io/obj_reader.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"

namespace occlusion {
namespace {

const std::string kPlyHead =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\n";

// What -rgoc writes (write_mesh_ply: unshared vertices, groups by comment)
// reads back as the same triangles in the same groups.
TEST(PlyMeshReader, ReadsWhatTheMeshWriterWrites) {
  testing::ScratchDirectory dir;
  const TriangleMesh room = read_obj(std::string(OCCLUSION_SOURCE_DIR) + "/files/sample_room.obj");
  std::vector<float> values(room.face_count(), 0.5f);
  write_mesh_ply(dir.file("room.ply"), room, values, "visible_fraction");
  const TriangleMesh back = read_mesh(dir.file("room.ply"));
  ASSERT_EQ(back.face_count(), room.face_count());
  EXPECT_EQ(back.vertices.size(), 3 * room.face_count());
  EXPECT_EQ(back.group_names, room.group_names);
  EXPECT_EQ(back.face_group, room.face_group);
  for (std::size_t f = 0; f < back.face_count(); ++f) {
    for (int k = 0; k < 3; ++k) {
      // PLY vertices are float: the OBJ's double coordinates, rounded once.
      const Eigen::Vector3f as_written = room.vertices[room.faces[f][k]].cast<float>();
      ASSERT_EQ(back.vertices[back.faces[f][k]], as_written.cast<double>()) << "face " << f;
    }
  }
  EXPECT_EQ(read_mesh(std::string(OCCLUSION_SOURCE_DIR) + "/files/sample_room.obj").face_count(),
            room.face_count());
}

TEST(PlyMeshReader, PolygonsAreFannedAndUngroupedFacesAreDefault) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("quad.ply"),
                      kPlyHead +
                          "element face 1\nproperty list uchar uint vertex_index\nend_header\n"
                          "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  const TriangleMesh quad = read_mesh(dir.file("quad.ply"));
  ASSERT_EQ(quad.face_count(), 2u);
  EXPECT_EQ(quad.faces[1], (std::array<std::uint32_t, 3>{0, 2, 3}));
  EXPECT_EQ(quad.group_names, std::vector<std::string>{"default"});
  EXPECT_NEAR(quad.face_area(0) + quad.face_area(1), 1.0, 1e-12);
}

TEST(PlyMeshReader, Errors) {
  testing::ScratchDirectory dir;
  const auto expect = [&](const std::string& name, const std::string& text,
                          const std::string& message) {
    testing::write_text(dir.file(name), text);
    testing::expect_input_error([&] { read_mesh(dir.file(name)); }, name, 0, message);
  };
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n2 2 0\n";
  expect("cloud.ply", kPlyHead + "end_header\n" + points, "a point cloud, not a mesh");
  expect("range.ply", kPlyHead + face + points + "3 0 1 4\n",
         "face 0: vertex index 4 is out of range");
  expect("flat.ply", kPlyHead + face + "0 0 0\n1 0 0\n2 0 0\n3 0 0\n3 0 1 2\n",
         "no faces with an area: all 1 are degenerate (first, face 0: degenerate face (zero "
         "area): vertices 0, 1, 2 are collinear)");
  expect("mesh.stl", "solid x\n", "(.obj or .ply");
  testing::write_text(dir.file("two.ply"), kPlyHead + face + points + "2 0 1\n");
  testing::expect_input_error([&] { read_mesh(dir.file("two.ply")); }, "two.ply", 14,
                              "face has 2 vertices, needs at least 3");
}

}  // namespace
}  // namespace occlusion
