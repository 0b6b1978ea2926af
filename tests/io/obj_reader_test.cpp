#include "occlusion/io/obj_reader.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/scratch_directory.hpp"

namespace occlusion {
namespace {

using Face = std::array<std::uint32_t, 3>;

const char* const kUnitSquare =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n";

TEST(ObjReader, ReadsVerticesAndATriangle) {
  const TriangleMesh mesh = parse_obj("v 0.5 -2 3e2\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0], Eigen::Vector3d(0.5, -2.0, 300.0));
  EXPECT_EQ(mesh.vertices[2], Eigen::Vector3d(0.0, 1.0, 0.0));
  ASSERT_EQ(mesh.faces.size(), 1u);
  EXPECT_EQ(mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_NO_THROW(mesh.validate());
}

TEST(ObjReader, IgnoresWeightAndColourAfterXyz) {
  const TriangleMesh mesh =
      parse_obj("v 1 2 3 1.0\nv 4 5 6 0.1 0.2 0.3\nv 7 8 10 0.5 0.5 0.5 1.0\nf 1 2 3\n", "t.obj");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0], Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(mesh.vertices[1], Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(mesh.vertices[2], Eigen::Vector3d(7, 8, 10));
}

TEST(ObjReader, AcceptsSignsAndExponents) {
  const TriangleMesh mesh =
      parse_obj("v +1 -0 .5\nv 1E-3 2.5e+1 -1e0\nv 0 0 1\nf +1 2 3\n", "t.obj");
  EXPECT_EQ(mesh.vertices[0], Eigen::Vector3d(1.0, 0.0, 0.5));
  EXPECT_EQ(mesh.vertices[1], Eigen::Vector3d(0.001, 25.0, -1.0));
  EXPECT_EQ(mesh.faces[0], (Face{0, 1, 2}));
}

TEST(ObjReader, KeepsTinyCoordinatesThatUnderflowFloat) {
  // from_chars reports result_out_of_range for subnormal-ish values; they are still finite.
  const TriangleMesh mesh = parse_obj("v 1e-320 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj");
  EXPECT_GE(mesh.vertices[0].x(), 0.0);
  EXPECT_LT(mesh.vertices[0].x(), 1e-300);
}

TEST(ObjReader, ReadsEveryCornerForm) {
  const std::string text = std::string(kUnitSquare) +
                           "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
                           "f 1/1 2/2 3/3\n"
                           "f 1/1/1 3/3/1 4/2/1\n"
                           "f 2//1 3//1 4//1\n";
  const TriangleMesh mesh = parse_obj(text, "t.obj");
  ASSERT_EQ(mesh.faces.size(), 3u);
  EXPECT_EQ(mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(mesh.faces[1], (Face{0, 2, 3}));
  EXPECT_EQ(mesh.faces[2], (Face{1, 2, 3}));
}

TEST(ObjReader, ResolvesNegativeIndicesAgainstVerticesReadSoFar) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
      "f -3 -2 -1\n"
      "v 5 5 5\nv 6 5 5\nv 5 6 5\n"
      "f -3/-3 -2//-1 -1\n"
      "f 1 -2 -1\n";
  const TriangleMesh mesh = parse_obj(text, "t.obj");
  ASSERT_EQ(mesh.faces.size(), 3u);
  EXPECT_EQ(mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(mesh.faces[1], (Face{3, 4, 5}));
  EXPECT_EQ(mesh.faces[2], (Face{0, 4, 5}));
}

TEST(ObjReader, FanTriangulatesAQuad) {
  const TriangleMesh mesh = parse_obj(std::string(kUnitSquare) + "f 1 2 3 4\n", "t.obj");
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(mesh.faces[1], (Face{0, 2, 3}));
  EXPECT_DOUBLE_EQ(mesh.face_area(0) + mesh.face_area(1), 1.0);
}

TEST(ObjReader, FanTriangulatesAPentagon) {
  const TriangleMesh mesh =
      parse_obj("v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n", "t.obj");
  ASSERT_EQ(mesh.faces.size(), 3u);
  EXPECT_EQ(mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(mesh.faces[1], (Face{0, 2, 3}));
  EXPECT_EQ(mesh.faces[2], (Face{0, 3, 4}));
  EXPECT_EQ(mesh.face_group, (std::vector<std::uint32_t>{0, 0, 0}));
}

TEST(ObjReader, FacesBeforeAnyGroupAreInDefault) {
  const TriangleMesh mesh =
      parse_obj(std::string(kUnitSquare) + "f 1 2 3\ng wall\nf 1 3 4\n", "t.obj");
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"default", "wall"}));
  EXPECT_EQ(mesh.face_group, (std::vector<std::uint32_t>{0, 1}));
}

TEST(ObjReader, ListsOnlyGroupsWithFacesInFirstUseOrder) {
  const std::string text = std::string(kUnitSquare) +
                           "g empty_before\n"
                           "g b\nf 1 2 3\n"
                           "o a\nf 1 3 4\n"
                           "g never_used\n"
                           "g b\nf 2 3 4\n"
                           "g empty_at_end\n";
  const TriangleMesh mesh = parse_obj(text, "t.obj");
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"b", "a"}));
  EXPECT_EQ(mesh.face_group, (std::vector<std::uint32_t>{0, 1, 0}));
  EXPECT_NO_THROW(mesh.validate());
}

TEST(ObjReader, JoinsSeveralGroupNamesWithOneSpace) {
  const TriangleMesh mesh =
      parse_obj(std::string(kUnitSquare) + "g  chair \t leg   left\nf 1 2 3\n", "t.obj");
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"chair leg left"}));
}

TEST(ObjReader, GroupWithoutNameIsDefault) {
  const TriangleMesh mesh =
      parse_obj(std::string(kUnitSquare) + "f 1 2 3\ng x\nf 1 3 4\ng\nf 2 3 4\n", "t.obj");
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"default", "x"}));
  EXPECT_EQ(mesh.face_group, (std::vector<std::uint32_t>{0, 1, 0}));
}

TEST(ObjReader, SkipsStatementsThatDoNotChangeGeometry) {
  const std::string text =
      "# a comment\n"
      "mtllib scene.mtl\n"
      "v 0 0 0\nv 1 0 0\nv 0 1 0 # trailing comment\n"
      "vt 0.5 0.5\nvn 0 0 1\nvp 0.1 0.2\n"
      "usemtl red\ns 1\ns off\n"
      "l 1 2\np 3\n"
      "curv 0 1 1 2\nfrobnicate everything\n"
      "f 1 2 3 # done\n";
  const TriangleMesh mesh = parse_obj(text, "t.obj");
  EXPECT_EQ(mesh.vertices.size(), 3u);
  ASSERT_EQ(mesh.faces.size(), 1u);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"default"}));
}

TEST(ObjReader, AcceptsCrlfBlankLinesAndIndentation) {
  const std::string text =
      "\r\n   \r\n\tv 0 0 0\r\n  v\t1 0 0  \r\nv 0 1 0\r\n\r\n   f 1 2 3\r\ng  side \r\nf 1 2 3";
  const TriangleMesh mesh = parse_obj(text, "t.obj");
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[1], Eigen::Vector3d(1, 0, 0));
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"default", "side"}));
}

// Old Mac line ends (CR alone), also mixed with LF and CR LF in one file:
// every vertex is kept, so the faces index the vertices they were written for.
TEST(ObjReader, ReadsLinesEndingInCrAlone) {
  const TriangleMesh mesh = parse_obj(
      "v 0 0 0\rv 1 0 0\r\nv 1 1 0\rv 0 1 0\nf 1 2 3\rf 1 3 4\r\rg top\rf 1 2 4", "t.obj");
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.vertices[2], Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(mesh.vertices[3], Eigen::Vector3d(0, 1, 0));
  ASSERT_EQ(mesh.faces.size(), 3u);
  EXPECT_EQ(mesh.faces[1], (Face{0, 2, 3}));
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"default", "top"}));
}

TEST(ObjReader, JoinsContinuedLines) {
  const std::string text = std::string(kUnitSquare) + "f 1 2 \\\n 3 \\\r\n 4\n";
  const TriangleMesh mesh = parse_obj(text, "t.obj");
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.faces[1], (Face{0, 2, 3}));
}

TEST(ObjReader, AcceptsPositiveIndicesToVerticesDefinedLater) {
  const TriangleMesh mesh = parse_obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "t.obj");
  ASSERT_EQ(mesh.faces.size(), 1u);
  EXPECT_EQ(mesh.faces[0], (Face{0, 1, 2}));
}

TEST(ObjReader, DegeneracyThresholdIsRelativeToSceneSize) {
  // A micro-scale scene is fine: the threshold scales with the bounding box.
  EXPECT_NO_THROW(parse_obj("v 0 0 0\nv 1e-6 0 0\nv 0 1e-6 0\nf 1 2 3\n", "t.obj"));
  // A sliver of relative area 1e-9 of a 1 m scene is kept: it is thin, not empty.
  EXPECT_NO_THROW(
      parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.5 1e-9 0\nf 1 2 3\nf 1 2 4\n", "t.obj"));
}

TEST(ObjReader, ReadObjReadsAFile) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("square.obj");
  testing::write_text(path, std::string(kUnitSquare) + "g floor\nf 1 2 3 4\n");
  const TriangleMesh mesh = read_obj(path);
  EXPECT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"floor"}));
}

}  // namespace
}  // namespace occlusion
