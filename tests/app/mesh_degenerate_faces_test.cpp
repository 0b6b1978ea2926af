// -moc on a mesh with zero-area faces (as reconstructed rooms have) measures
// the mesh without them and says how many it skipped.

#include <gtest/gtest.h>

#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"

namespace occlusion {
namespace {

// A closed 4 m room (faces 1-12, 96 m^2) around the viewpoint and a 1 m box
// outside it (faces 13-24, 6 m^2): every room sample is seen and every box
// sample hidden, so the level is 6 / 102 whatever the samples.
const char* const kVertices =
    "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nv 0 0 4\nv 4 0 4\nv 4 4 4\nv 0 4 4\n"
    "v 6 1 1\nv 7 1 1\nv 7 2 1\nv 6 2 1\nv 6 1 2\nv 7 1 2\nv 6 2 2\nv 7 2 2\n"
    "v 2 0 0\n";  // vertex 17 lies on the room's edge 1-2
const char* const kRoom =
    "f 1 2 3\nf 1 3 4\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n"
    "f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
const char* const kBox =
    "f 9 10 11\nf 9 11 12\nf 13 14 16\nf 13 16 15\nf 9 10 14\nf 9 14 13\nf 10 11 16\n"
    "f 10 16 14\nf 11 12 15\nf 11 15 16\nf 12 9 13\nf 12 13 15\n";
// A repeated vertex, three collinear vertices and two corners at one point.
const char* const kDegenerate = "f 1 1 2\nf 1 17 2\nf 9 9 9\n";

MeshOcclusionReport measure(const std::string& path) {
  MeshOcclusionRequest request;
  request.path = path;
  request.viewpoints = ViewpointChoice::from_points({Eigen::Vector3d(2, 2, 2)});
  request.samples_per_unit_area = 20;
  request.threads = 2;
  return run_mesh_occlusion(request);
}

TEST(MeshDegenerateFaces, SkippedFacesChangeNoFigureAndAreReported) {
  testing::ScratchDirectory dir;
  const std::string clean = dir.file("clean.obj");
  const std::string appended = dir.file("appended.obj");
  const std::string interleaved = dir.file("interleaved.obj");
  testing::write_text(clean, std::string(kVertices) + kRoom + kBox);
  testing::write_text(appended, std::string(kVertices) + kRoom + kBox + kDegenerate);
  testing::write_text(interleaved,
                      std::string(kVertices) + kDegenerate + kRoom + "f 2 2 3\n" + kBox);

  const MeshOcclusionReport reference = measure(clean);
  EXPECT_EQ(reference.result.faces, 24u);
  EXPECT_EQ(reference.degenerate_faces_skipped, 0u);
  EXPECT_NEAR(reference.result.occlusion_level, 6.0 / 102.0, 1e-12);

  // Appended, every other face keeps its index and so its samples: the same run.
  const MeshOcclusionReport after = measure(appended);
  EXPECT_EQ(after.result.faces, 24u);
  EXPECT_EQ(after.result.samples, reference.result.samples);
  EXPECT_EQ(after.result.occlusion_level, reference.result.occlusion_level);
  EXPECT_EQ(after.result.face_visible_fraction, reference.result.face_visible_fraction);
  EXPECT_EQ(after.degenerate_faces_skipped, 3u);
  EXPECT_EQ(after.warnings.size(), reference.warnings.size() + 1);
  const std::string& warning = after.warnings.back();
  EXPECT_NE(warning.find("3 degenerate faces (zero area) were skipped"), std::string::npos)
      << warning;
  EXPECT_NE(warning.find("line 42: degenerate face (zero area): vertex 1 is used twice"),
            std::string::npos)
      << warning;
  EXPECT_EQ(to_json(after)["degenerate_faces_skipped"].asUInt64(), 3u);

  // Among the others: other samples, the same answer (each face wholly seen or hidden).
  const MeshOcclusionReport among = measure(interleaved);
  EXPECT_EQ(among.result.faces, 24u);
  EXPECT_EQ(among.degenerate_faces_skipped, 4u);
  EXPECT_EQ(among.result.total_area, reference.result.total_area);
  EXPECT_EQ(among.result.occlusion_level, reference.result.occlusion_level);
  EXPECT_EQ(among.result.face_visible_fraction, reference.result.face_visible_fraction);
}

}  // namespace
}  // namespace occlusion
