// The study's scan_model laser: each run scanned from its viewpoints by the
// virtual laser scanner on the scene's mesh (the OBJ beside it), judged
// against that mesh: returns on its surfaces, labelled by its groups,
// coloured from the scene's points, the tripod's blind cone left unseen; the
// scan model in the rows' fingerprint; a scene without a mesh refused before
// the first run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/study_job.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/obj_writer.hpp"

namespace occlusion {
namespace {

using testing::ScratchDirectory;

const std::string kSource = OCCLUSION_SOURCE_DIR;
constexpr double kX = 4.0, kY = 3.0, kZ = 2.5;  // the box room's size

// One quad (two triangles) of the box room in group `group`.
void add_quad(TriangleMesh& mesh, std::uint32_t group, const Eigen::Vector3d& o,
              const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {o, o + u, o + u + v, o + v});
  mesh.faces.push_back({first, first + 1, first + 2});
  mesh.faces.push_back({first, first + 2, first + 3});
  mesh.face_group.insert(mesh.face_group.end(), {group, group});
}

// A closed box room, 4 x 3 x 2.5 m: floor_1, ceiling_1 and four walls as an
// OBJ, and its points every 5 cm as a labelled PLY beside it, the floor red,
// the ceiling blue, the walls green.
std::string write_box_room(const ScratchDirectory& dir) {
  TriangleMesh mesh;
  mesh.group_names = {"floor_1", "ceiling_1", "wall_1", "wall_2", "wall_3", "wall_4"};
  const Eigen::Vector3d x(kX, 0, 0), y(0, kY, 0), z(0, 0, kZ), o(0, 0, 0);
  add_quad(mesh, 0, o, x, y);
  add_quad(mesh, 1, z, x, y);
  add_quad(mesh, 2, o, x, z);
  add_quad(mesh, 3, y, x, z);
  add_quad(mesh, 4, o, y, z);
  add_quad(mesh, 5, x, y, z);
  write_obj(dir.file("room.obj"), mesh);

  PointCloud cloud;
  cloud.class_names = {"floor", "ceiling", "wall"};
  const double step = 0.05;
  for (std::size_t face = 0; face < mesh.face_count(); face += 2) {
    const std::uint32_t group = mesh.face_group[face];
    const int label = group < 2 ? static_cast<int>(group) : 2;
    const std::array<std::uint8_t, 3> colour = label == 0 ? std::array<std::uint8_t, 3>{200, 0, 0}
                                               : label == 1
                                                   ? std::array<std::uint8_t, 3>{0, 0, 200}
                                                   : std::array<std::uint8_t, 3>{0, 200, 0};
    const auto& f = mesh.faces[face];
    const Eigen::Vector3d a = mesh.vertices[f[0]], u = mesh.vertices[f[1]] - a,
                          v = mesh.vertices[f[2]] - mesh.vertices[f[1]];
    const int nu = static_cast<int>(std::lround(u.norm() / step));
    const int nv = static_cast<int>(std::lround(v.norm() / step));
    for (int i = 0; i < nu; ++i) {
      for (int j = 0; j < nv; ++j) {
        const Eigen::Vector3d p = a + (i + 0.5) / nu * u + (j + 0.5) / nv * v;
        cloud.positions.push_back(p.cast<float>());
        cloud.labels.push_back(label);
        cloud.colours.push_back(colour);
      }
    }
  }
  write_cloud(dir.file("room.ply"), cloud);
  return dir.file("room.ply");
}

StudyRequest laser_study(const std::string& scene, const std::string& out) {
  StudyRequest request;
  request.scenes = {scene};
  request.configurations = {{"centre", ViewpointChoice::from_points({{2.0, 1.5, 1.5}})}};
  request.tracing.point_radius = 0.05;
  request.tracing.num_rays_per_vp = 400;
  request.tracing.exterior = false;
  request.scan_model = kLaserScan;
  request.laser.azimuth_step_deg = 2.0;
  request.laser.elevation_step_deg = 2.0;
  request.segmenter =
      "python3 '" + kSource + "/tests/support/study_segmenter.py' wall {input} {output}";
  request.out = out;
  return request;
}

double number(const CsvTable& table, std::size_t row, const std::string& column) {
  return std::stod(table.rows.at(row).at(table.column(column)));
}

TEST(StudySensor, ALaserScanLiesOnTheMeshLabelledAndColouredAsItsSurfaces) {
  const ScratchDirectory dir;
  const std::string scene = write_box_room(dir);
  const StudyReport report = run_study(laser_study(scene, dir.file("study")));
  ASSERT_EQ(report.runs_failed, 0u);
  const PointCloud scan = read_cloud(dir.file("study/runs/room__centre.scan.ply"));
  // 180 columns x 76 rows (-60 to 90 degrees in 2 degree steps), all inside
  // the closed room and beyond the 0.5 m minimum range; a few lost at
  // grazing angles in the corners.
  EXPECT_GT(scan.size(), 180u * 76u * 9 / 10);
  EXPECT_LE(scan.size(), 180u * 76u);
  EXPECT_EQ(static_cast<std::size_t>(number(report.table, 0, "scanned_points")), scan.size());
  std::size_t floor = 0;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const Eigen::Vector3d p = scan.positions[i].cast<double>();
    const std::string& name = scan.class_names.at(scan.labels[i]);
    // 3 mm range noise: every return within 2 cm of the surface it names.
    const double off = name == "floor"     ? std::abs(p.z())
                       : name == "ceiling" ? std::abs(p.z() - kZ)
                                           : std::min({std::abs(p.x()), std::abs(p.x() - kX),
                                                       std::abs(p.y()), std::abs(p.y() - kY)});
    ASSERT_LT(off, 0.02) << name << " return at " << p.transpose();
    // Coloured from the scene's nearest point: the floor's red, and so on
    // (away from the edges, where another surface's point may be nearest).
    int near_surfaces = 0;
    for (const double d : {p.x(), p.x() - kX, p.y(), p.y() - kY, p.z(), p.z() - kZ})
      near_surfaces += std::abs(d) < 0.06 ? 1 : 0;
    const auto& c = scan.colours.at(i);
    if (near_surfaces == 1) {
      EXPECT_EQ(c[0] > 100, name == "floor") << name << " at " << p.transpose();
      EXPECT_EQ(c[2] > 100, name == "ceiling") << name << " at " << p.transpose();
    }
    if (name == "floor") {
      ++floor;
      // Nothing below -60 degrees: the floor within 1.5 / tan 60 = 0.87 m
      // of the tripod's foot is the scanner's blind cone.
      EXPECT_GT(std::hypot(p.x() - 2.0, p.y() - 1.5), 0.85) << p.transpose();
    }
  }
  EXPECT_GT(floor, 100u);
  // Covered: every wall and ceiling point, the floor outside the blind cone.
  const double cone = M_PI * 0.866 * 0.866;
  const double total_area = 2 * kX * kY + 2 * (kX + kY) * kZ;
  EXPECT_NEAR(number(report.table, 0, "visible_fraction"), 1.0 - cone / total_area, 0.02);
}

TEST(StudySensor, TheScanModelIsInTheFingerprintAndAnIdealStudyIgnoresTheLaser) {
  const ScratchDirectory dir;
  const std::string scene = write_box_room(dir);
  StudyRequest ideal = laser_study(scene, dir.file("ideal"));
  ideal.scan_model = kIdealScan;
  const StudyReport made = run_study(ideal);
  // The laser's keys change nothing an ideal scan makes: the study resumes.
  ideal.laser.azimuth_step_deg = 3.0;
  EXPECT_EQ(run_study(ideal).runs_computed, 0u);
  // The same folder with the laser is other rows: refused, naming the key.
  StudyRequest laser = laser_study(scene, dir.file("ideal"));
  try {
    run_study(laser);
    FAIL() << "resuming ideal rows with the laser was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("scan_model (was absent, now \"laser\")"),
              std::string::npos)
        << e.what();
  }
  const StudyReport fresh = run_study(laser_study(scene, dir.file("laser")));
  EXPECT_NE(made.table.rows[0][made.table.column("fingerprint")],
            fresh.table.rows[0][fresh.table.column("fingerprint")]);
  EXPECT_NE(made.table.rows[0][made.table.column("scanned_points")],
            fresh.table.rows[0][fresh.table.column("scanned_points")]);
}

TEST(StudySensor, ASceneWithoutItsMeshStopsTheStudyBeforeItsFirstRun) {
  const ScratchDirectory dir;
  const std::string scene = write_box_room(dir);
  std::filesystem::remove(dir.file("room.obj"));
  try {
    run_study(laser_study(scene, dir.file("study")));
    FAIL() << "a laser study without the scene's mesh ran";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.file("room.obj")), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--mesh"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("study/study.csv")));
}

}  // namespace
}  // namespace occlusion
