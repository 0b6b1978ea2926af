// ScanNet scenes: a folder, its labels file, or its mesh with the labels file
// beside it load as one cloud labelled with NYU40 ids and names; a labels file
// that is not the mesh's is refused.

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/core/nyu40_classes.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "support/scannet_scene.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<std::uint8_t, 3>;

// Four vertices of a floor quad and a wall, labelled floor (2), wall (1),
// unannotated (0) and shower curtain (28).
testing::ScanNetScene small_scene() {
  testing::ScanNetScene scene;
  scene.positions = {
      {0.5f, 1.25f, 0.0f}, {3.0f, 0.0f, 2.5f}, {0.0f, 2.0f, 0.1f}, {1.0f, 1.0f, 1.0f}};
  scene.colours = {{10, 20, 30}, {40, 50, 60}, {70, 80, 90}, {100, 110, 120}};
  scene.labels = {2, 1, 0, 28};
  scene.faces = {{0, 1, 2}, {0, 2, 3}};
  return scene;
}

void expect_scene(const PointCloud& cloud) {
  const testing::ScanNetScene scene = small_scene();
  ASSERT_EQ(cloud.size(), 4u);
  EXPECT_EQ(cloud.positions, scene.positions);
  EXPECT_EQ(cloud.colours, scene.colours);  // the mesh's colours, not the labels' palette
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{2, 1, 0, 28}));
  ASSERT_EQ(cloud.class_names.size(), 41u);
  EXPECT_EQ(cloud.class_names[0], "unannotated");
  EXPECT_EQ(cloud.class_names[1], "wall");
  EXPECT_EQ(cloud.class_names[2], "floor");
  EXPECT_EQ(cloud.class_names[24], "refridgerator");  // ScanNet's nyu40class spelling
  EXPECT_EQ(cloud.class_names[28], "shower curtain");
  EXPECT_EQ(cloud.class_names[40], "otherprop");
}

TEST(ScanNetReader, FolderLabelsFileAndMeshLoadAsOneLabelledCloud) {
  testing::ScratchDirectory dir;
  const fs::path folder = testing::write_scannet_scene(dir.path(), "scene0007_01", small_scene());
  CloudReadReport report;
  expect_scene(read_cloud(folder.string(), {}, &report));
  ASSERT_EQ(report.extra_fields.size(), 1u);  // the mesh's alpha, once
  EXPECT_EQ(report.extra_fields[0].name, "alpha");
  expect_scene(read_cloud(folder.string() + "/"));
  expect_scene(read_cloud((folder / "scene0007_01_vh_clean_2.labels.ply").string()));
  expect_scene(read_cloud((folder / "scene0007_01_vh_clean_2.ply").string()));
}

TEST(ScanNetReader, LabelsFileAloneKeepsItsOwnPaletteColours) {
  testing::ScratchDirectory dir;
  const fs::path folder = testing::write_scannet_scene(dir.path(), "scene0001_00", small_scene());
  fs::remove(folder / "scene0001_00_vh_clean_2.ply");
  const PointCloud cloud = read_cloud((folder / "scene0001_00_vh_clean_2.labels.ply").string());
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{2, 1, 0, 28}));
  EXPECT_EQ(cloud.class_names, nyu40_class_names());
  EXPECT_EQ(cloud.colours[1], (Rgb{6, 7, 8}));  // label 1's palette entry as written
  EXPECT_EQ(read_cloud(folder.string()).labels, cloud.labels);
}

TEST(ScanNetReader, MeshWithoutLabelsIsAPlainCloud) {
  testing::ScratchDirectory dir;
  const fs::path folder = testing::write_scannet_scene(dir.path(), "scene0002_00", small_scene());
  fs::remove(folder / "scene0002_00_vh_clean_2.labels.ply");
  const PointCloud cloud = read_cloud((folder / "scene0002_00_vh_clean_2.ply").string());
  EXPECT_EQ(cloud.size(), 4u);
  EXPECT_FALSE(cloud.has_labels());
  EXPECT_EQ(read_cloud(folder.string()).colours, small_scene().colours);
}

TEST(ScanNetReader, LabelsOfOtherVerticesAreRefused) {
  testing::ScratchDirectory dir;
  const fs::path folder = testing::write_scannet_scene(dir.path(), "scene0003_00", small_scene());
  const std::string labels = (folder / "scene0003_00_vh_clean_2.labels.ply").string();

  testing::ScanNetScene fewer = small_scene();
  fewer.positions.pop_back();
  fewer.labels.pop_back();
  fewer.faces.pop_back();
  testing::write_text(labels, testing::scannet_labels_ply(fewer));
  testing::expect_input_error([&] { read_cloud(folder.string()); }, "labels.ply", 0,
                              "has 3 vertices and the mesh");

  testing::ScanNetScene moved = small_scene();
  moved.positions[2].z() += 0.001f;
  testing::write_text(labels, testing::scannet_labels_ply(moved));
  testing::expect_input_error([&] { read_cloud(folder.string()); }, "labels.ply", 0,
                              "vertex 2 lies at (0.000000, 2.000000, 0.101000)");

  testing::ScanNetScene reordered = small_scene();
  std::swap(reordered.positions[0], reordered.positions[1]);
  testing::write_text(labels, testing::scannet_labels_ply(reordered));
  testing::expect_input_error([&] { read_cloud(labels); }, "labels.ply", 0,
                              "not for this mesh's vertices");
}

TEST(ScanNetReader, LabelsThatAreNoNyu40IdsAreRefused) {
  testing::ScratchDirectory dir;
  testing::ScanNetScene scene = small_scene();
  scene.labels[3] = 41;
  const fs::path folder = testing::write_scannet_scene(dir.path(), "scene0004_00", scene);
  testing::expect_input_error([&] { read_cloud(folder.string()); }, "labels.ply", 0,
                              "vertex 3 has label 41, which is no NYU40 id");
}

TEST(ScanNetReader, ALabelsFileWithoutLabelsIsRefused) {
  testing::ScratchDirectory dir;
  const fs::path folder = testing::write_scannet_scene(dir.path(), "scene0005_00", small_scene());
  testing::write_text((folder / "scene0005_00_vh_clean_2.labels.ply").string(),
                      testing::scannet_mesh_ply(small_scene()));
  testing::expect_input_error([&] { read_cloud(folder.string()); }, "labels.ply", 0,
                              "has no label property");
}

TEST(ScanNetReader, AFolderWithoutTheSceneFilesIsNoScanNetScene) {
  testing::ScratchDirectory dir;
  fs::create_directories(dir.path() / "scene0006_00");
  testing::write_text(dir.file("scene0006_00/scene0006_00_vh_clean.ply"), "not read");
  // Read as an S3DIS folder, which it is not either.
  testing::expect_input_error([&] { read_cloud(dir.file("scene0006_00")); }, "scene0006_00", 0, "");
}

// A vertex with a non-finite coordinate is dropped from a cloud, and from
// the labels file read beside it: the counts compared were of the vertices
// kept in the mesh and of all in the labels file, so the same scene was
// refused as "4 vertices and the mesh has 3", and a NaN in the labels file
// alone as "4 vertices and the mesh has 4".
TEST(ScanNetReader, AVertexThatIsNotFiniteIsDroppedFromBothFilesOrNamed) {
  testing::ScratchDirectory dir;
  testing::ScanNetScene scene = small_scene();
  scene.positions[1].x() = std::numeric_limits<float>::quiet_NaN();
  const fs::path both = testing::write_scannet_scene(dir.path(), "scene0009_00", scene);
  CloudReadReport report;
  const PointCloud cloud = read_cloud(both.string(), {}, &report);
  EXPECT_EQ(report.dropped_nan, 1u);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{2, 0, 28}));
  EXPECT_EQ(cloud.colours[1], (Rgb{70, 80, 90}));

  const fs::path labels_only =
      testing::write_scannet_scene(dir.path(), "scene0010_00", small_scene());
  testing::write_text((labels_only / "scene0010_00_vh_clean_2.labels.ply").string(),
                      testing::scannet_labels_ply(scene));
  testing::expect_input_error([&] { read_cloud(labels_only.string()); }, "labels.ply", 0,
                              "has 4 vertices, as the mesh");
  testing::expect_input_error([&] { read_cloud(labels_only.string()); }, "labels.ply", 0,
                              "but 1 of them with a non-finite coordinate where the mesh has 0");

  const fs::path mesh_only =
      testing::write_scannet_scene(dir.path(), "scene0011_00", small_scene());
  testing::write_text((mesh_only / "scene0011_00_vh_clean_2.ply").string(),
                      testing::scannet_mesh_ply(scene));
  testing::expect_input_error([&] { read_cloud(mesh_only.string()); }, "labels.ply", 0,
                              "but 0 of them with a non-finite coordinate where the mesh has 1");
  // As a mesh, a vertex that is not finite is refused where it is.
  testing::expect_input_error([&] { read_mesh(mesh_only.string()); }, "vh_clean_2.ply", 0,
                              "vertex 1");
}

TEST(ScanNetReader, TheMeshGroupsItsFacesByClass) {
  testing::ScratchDirectory dir;
  testing::ScanNetScene scene = small_scene();
  scene.positions.push_back({2.0f, 2.0f, 0.0f});
  scene.colours.push_back({1, 2, 3});
  scene.labels.push_back(2);
  // Labels 2 1 0 28 2: faces (0 1 4) floor by two corners, (0 2 3) mixed,
  // (1 3 3) degenerate, (4 0 1) floor.
  scene.faces = {{0, 1, 4}, {0, 2, 3}, {1, 3, 3}, {4, 0, 1}};
  const fs::path folder = testing::write_scannet_scene(dir.path(), "scene0008_00", scene);
  MeshReadReport report;
  const TriangleMesh mesh = read_mesh(folder.string(), &report);
  ASSERT_EQ(mesh.face_count(), 3u);
  EXPECT_EQ(report.degenerate_faces, 1u);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"floor", "mixed"}));
  EXPECT_EQ(mesh.face_group, (std::vector<std::uint32_t>{0, 1, 0}));
  mesh.validate();
  // The mesh file with its labels beside it is the same scene.
  EXPECT_EQ(read_mesh((folder / "scene0008_00_vh_clean_2.ply").string()).group_names,
            mesh.group_names);
  // Without labels it is a plain PLY mesh.
  fs::remove(folder / "scene0008_00_vh_clean_2.labels.ply");
  EXPECT_EQ(read_mesh((folder / "scene0008_00_vh_clean_2.ply").string()).group_names,
            (std::vector<std::string>{"default"}));
}

}  // namespace
}  // namespace occlusion
