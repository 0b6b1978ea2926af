#include "occlusion/io/ply_mesh_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/scratch_directory.hpp"
#include "occlusion/io/colour_ramp.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {
namespace {

// Two triangles of a unit square in two groups.
TriangleMesh two_face_mesh() {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, -2.25}};
  mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  mesh.face_group = {1, 0};
  mesh.group_names = {"floor", "north wall"};
  return mesh;
}

// Reads little-endian values independently of the host's byte order.
class LittleEndianReader {
 public:
  LittleEndianReader(const std::string& bytes, std::size_t offset)
      : bytes_(bytes), offset_(offset) {}
  std::uint8_t u8() { return static_cast<std::uint8_t>(bytes_.at(offset_++)); }
  std::uint32_t u32() {
    std::uint32_t value = 0;
    for (int shift = 0; shift < 32; shift += 8) value |= std::uint32_t{u8()} << shift;
    return value;
  }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  float f32() {
    const std::uint32_t bits = u32();
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  std::size_t offset() const { return offset_; }

 private:
  const std::string& bytes_;
  std::size_t offset_;
};

struct PlyFile {
  std::vector<std::string> header_lines;
  std::string bytes;
  std::size_t body_offset = 0;
};

PlyFile read_ply(const std::string& path) {
  PlyFile ply;
  ply.bytes = testing::read_bytes(path);
  const std::string end = "end_header\n";
  const std::size_t end_at = ply.bytes.find(end);
  EXPECT_NE(end_at, std::string::npos);
  ply.body_offset = end_at + end.size();
  std::istringstream header(ply.bytes.substr(0, ply.body_offset));
  for (std::string line; std::getline(header, line);) ply.header_lines.push_back(line);
  return ply;
}

TEST(PlyMeshWriter, HeaderDeclaresUnsharedVerticesValuesAndGroups) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("mesh.ply");
  write_mesh_ply(path, two_face_mesh(), {0.25f, 1.0f}, "visible_fraction");
  const PlyFile ply = read_ply(path);
  const std::vector<std::string> expected = {
      "ply",
      "format binary_little_endian 1.0",
      "comment written by occlusion",
      "comment visible_fraction and group_id: one value per face, repeated on the face's own 3 "
      "vertices as scalar_visible_fraction and scalar_group_id so that CloudCompare loads them "
      "as scalar fields",
      "comment colour: viridis ramp of visible_fraction clamped to [0,1], grey where it is NaN "
      "(no data)",
      "comment group 0 floor",
      "comment group 1 north wall",
      "element vertex 6",
      "property float x",
      "property float y",
      "property float z",
      "property uchar red",
      "property uchar green",
      "property uchar blue",
      "property float scalar_visible_fraction",
      "property int scalar_group_id",
      "element face 2",
      "property list uchar int vertex_indices",
      "property float visible_fraction",
      "property int group_id",
      "end_header",
  };
  EXPECT_EQ(ply.header_lines, expected);
}

TEST(PlyMeshWriter, BodyHoldsPositionsColoursValuesAndGroups) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("mesh.ply");
  const TriangleMesh mesh = two_face_mesh();
  const std::vector<float> values = {0.25f, 1.0f};
  write_mesh_ply(path, mesh, values, "visible_fraction");
  const PlyFile ply = read_ply(path);
  constexpr std::size_t kVertexBytes = 23, kFaceBytes = 21;
  ASSERT_EQ(ply.bytes.size(), ply.body_offset + 6 * kVertexBytes + 2 * kFaceBytes);

  LittleEndianReader in(ply.bytes, ply.body_offset);
  for (std::size_t f = 0; f < 2; ++f) {
    const auto rgb = colour_ramp(values[f]);
    for (int corner = 0; corner < 3; ++corner) {
      const Eigen::Vector3d& p = mesh.vertices[mesh.faces[f][corner]];
      EXPECT_EQ(in.f32(), static_cast<float>(p.x()));
      EXPECT_EQ(in.f32(), static_cast<float>(p.y()));
      EXPECT_EQ(in.f32(), static_cast<float>(p.z()));
      EXPECT_EQ(in.u8(), rgb[0]);
      EXPECT_EQ(in.u8(), rgb[1]);
      EXPECT_EQ(in.u8(), rgb[2]);
      EXPECT_EQ(in.f32(), values[f]);
      EXPECT_EQ(in.i32(), static_cast<std::int32_t>(mesh.face_group[f]));
    }
  }
  for (std::size_t f = 0; f < 2; ++f) {
    EXPECT_EQ(in.u8(), 3);
    for (int corner = 0; corner < 3; ++corner) {
      EXPECT_EQ(in.i32(), static_cast<std::int32_t>(3 * f + corner));
    }
    EXPECT_EQ(in.f32(), values[f]);
    EXPECT_EQ(in.i32(), static_cast<std::int32_t>(mesh.face_group[f]));
  }
  EXPECT_EQ(in.offset(), ply.bytes.size());
  // The two faces have different values, so the test would notice swapped colours.
  EXPECT_NE(colour_ramp(values[0]), colour_ramp(values[1]));
}

TEST(PlyMeshWriter, NanValueIsWrittenAndColouredGrey) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("mesh.ply");
  write_mesh_ply(path, two_face_mesh(), {std::numeric_limits<float>::quiet_NaN(), 0.0f}, "v");
  const PlyFile ply = read_ply(path);
  LittleEndianReader in(ply.bytes, ply.body_offset + 12);
  EXPECT_EQ(in.u8(), 128);
  EXPECT_EQ(in.u8(), 128);
  EXPECT_EQ(in.u8(), 128);
  EXPECT_TRUE(std::isnan(in.f32()));
}

TEST(PlyMeshWriter, RejectsWrongNumberOfValues) {
  testing::ScratchDirectory dir;
  EXPECT_THROW(write_mesh_ply(dir.file("m.ply"), two_face_mesh(), {0.5f}, "v"),
               std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PlyMeshWriter, RejectsValueNamesThatBreakTheHeader) {
  testing::ScratchDirectory dir;
  for (const char* name : {"", "two words", "line\nbreak", "red", "group_id"}) {
    EXPECT_THROW(write_mesh_ply(dir.file("m.ply"), two_face_mesh(), {0.5f, 0.5f}, name),
                 std::invalid_argument)
        << name;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PlyMeshWriter, RejectsAnInvalidMesh) {
  testing::ScratchDirectory dir;
  TriangleMesh mesh = two_face_mesh();
  mesh.faces[1][2] = 9;
  EXPECT_THROW(write_mesh_ply(dir.file("m.ply"), mesh, {0.5f, 0.5f}, "v"), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PlyMeshWriter, MissingDirectoryIsAnOutputError) {
  testing::ScratchDirectory dir;
  EXPECT_THROW(write_mesh_ply(dir.file("missing/m.ply"), two_face_mesh(), {0.5f, 0.5f}, "v"),
               OutputError);
}

}  // namespace
}  // namespace occlusion
