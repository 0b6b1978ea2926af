// Zero-area triangles (real reconstructed meshes hold a few) are skipped and
// counted by both mesh readers, with the rest of the mesh and its groups intact.

#include <gtest/gtest.h>

#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "occlusion/io/obj_reader.hpp"

namespace occlusion {
namespace {

const char* const kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1-3

TEST(DegenerateFaces, RepeatedVertexIsSkippedAndCounted) {
  MeshReadReport report;
  const TriangleMesh mesh =
      parse_obj(std::string(kTriangle) + "f 1 2 3\nf 1 2 2\nf 3 1 -1\n", "t.obj", &report);
  ASSERT_EQ(mesh.face_count(), 1u);
  EXPECT_EQ(mesh.faces[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(report.degenerate_faces, 2u);
  EXPECT_EQ(report.first_degenerate,
            "line 5: degenerate face (zero area): vertex 2 is used twice in one triangle");
}

TEST(DegenerateFaces, CollinearCoincidentAndSliverTrianglesAreSkipped) {
  MeshReadReport report;
  // Faces on line 7 collinear (vertex 4 on the x axis), 8 two vertices at one
  // point, 9 a sliver of area 0.5e-12 < 1e-12 x diagonal^2 (5).
  const std::string text = std::string(kTriangle) +
                           "v 2 0 0\nv 1 0 0\nv 0.5 1e-12 0\nf 1 2 4\nf 1 2 5\nf 1 2 6\nf 1 2 3\n";
  const TriangleMesh mesh = parse_obj(text, "t.obj", &report);
  ASSERT_EQ(mesh.face_count(), 1u);
  EXPECT_EQ(report.degenerate_faces, 3u);
  EXPECT_EQ(report.first_degenerate,
            "line 7: degenerate face (zero area): vertices 1, 2, 4 are collinear");
}

TEST(DegenerateFaces, AGroupLeftWithoutFacesDisappears) {
  MeshReadReport report;
  const TriangleMesh mesh = parse_obj(
      std::string(kTriangle) + "g a\nf 1 2 3\ng b\nf 1 1 2\ng c\nf 3 2 1\n", "t.obj", &report);
  ASSERT_EQ(mesh.face_count(), 2u);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"a", "c"}));
  EXPECT_EQ(mesh.face_group, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(report.degenerate_faces, 1u);
  mesh.validate();
}

TEST(DegenerateFaces, ADegenerateFanTriangleLeavesTheRestOfItsPolygon) {
  MeshReadReport report;
  // The quad's second fan triangle (1, 3, 4) is collinear: vertex 4 lies on edge 1-3.
  const TriangleMesh mesh =
      parse_obj(std::string(kTriangle) + "v 0 0.5 0\nf 1 2 3 4\n", "t.obj", &report);
  ASSERT_EQ(mesh.face_count(), 1u);
  EXPECT_EQ(report.first_degenerate.rfind("line 5: ", 0), 0u) << report.first_degenerate;
}

TEST(DegenerateFaces, PlyFacesAreCountedByTheirFileIndex) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("m.ply"),
                      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                      "property float y\nproperty float z\nelement face 3\n"
                      "property list uchar int vertex_indices\nproperty int group_id\n"
                      "end_header\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n3 0 1 2 4\n3 0 1 3 5\n"
                      "3 2 1 0 6\n");
  MeshReadReport report;
  const TriangleMesh mesh = read_mesh(dir.file("m.ply"), &report);
  ASSERT_EQ(mesh.face_count(), 2u);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"group 4", "group 6"}));
  EXPECT_EQ(report.degenerate_faces, 1u);
  EXPECT_EQ(report.first_degenerate,
            "face 1: degenerate face (zero area): vertices 0, 1, 3 are collinear");
  // Without a report the mesh is the same.
  EXPECT_EQ(read_mesh(dir.file("m.ply")).faces, mesh.faces);
}

}  // namespace
}  // namespace occlusion
