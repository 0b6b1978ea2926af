#include "occlusion/io/obj_writer.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "io/scratch_directory.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/obj_reader.hpp"

namespace occlusion {
namespace {

using testing::read_bytes;
using testing::ScratchDirectory;

// Coordinates that decimal printing with too few digits would change, two
// groups with a run of each, and a group without faces.
TriangleMesh mesh_with_groups() {
  TriangleMesh mesh;
  mesh.vertices = {{0.1, 0.2, 0.3}, {1.0 / 3.0, -2e-17, 1e3}, {1, 1, 0.5}, {0, 1, -2.25}};
  mesh.faces = {{0, 1, 2}, {0, 2, 3}, {1, 2, 3}};
  mesh.face_group = {2, 2, 0};
  mesh.group_names = {"cluster_0", "cluster_1", "cluster 2\nsecond line"};
  return mesh;
}

TEST(ObjWriter, ReadsBackExactly) {
  const ScratchDirectory dir;
  const TriangleMesh mesh = mesh_with_groups();
  write_obj(dir.file("mesh.obj"), mesh, "estimated\nfrom a cloud");
  const TriangleMesh back = read_obj(dir.file("mesh.obj"));
  EXPECT_EQ(back.vertices, mesh.vertices);
  EXPECT_EQ(back.faces, mesh.faces);
  // Groups in order of their first face; the empty one is not written.
  ASSERT_EQ(back.group_names, (std::vector<std::string>{"cluster 2 second line", "cluster_0"}));
  EXPECT_EQ(back.face_group, (std::vector<std::uint32_t>{0, 0, 1}));

  const std::string text = read_bytes(dir.file("mesh.obj"));
  EXPECT_EQ(text.rfind("# estimated\n# from a cloud\nv ", 0), 0u) << text;
}

TEST(ObjWriter, RejectsInvalidMeshesAndUnwritablePaths) {
  const ScratchDirectory dir;
  TriangleMesh bad = mesh_with_groups();
  bad.faces[0][1] = 9;
  EXPECT_THROW(write_obj(dir.file("bad.obj"), bad), std::invalid_argument);
  EXPECT_THROW(write_obj(dir.file("missing/dir/mesh.obj"), mesh_with_groups()), OutputError);
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace occlusion
