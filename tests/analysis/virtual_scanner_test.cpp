// The virtual scanner against the truth: returns lie on the mesh where no
// noise is asked for, the noise has the sigma of its formula, a wall hides
// what stands behind it, and the camera's depth steps are the disparity
// formula's, worked by hand.

#include "occlusion/analysis/virtual_scanner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "support/scenes.hpp"

namespace occlusion {
namespace {

using testing::add_box;
using testing::add_quad;

// A closed 6 x 4 x 3 room with a table-like box in it.
TriangleMesh room_with_box() {
  TriangleMesh mesh;
  add_box(mesh, {0, 0, 0}, {6, 4, 3}, "room", 2);
  add_box(mesh, {4, 1, 0}, {5, 2, 1}, "table_1");
  return mesh;
}

LaserScannerModel coarse_laser() {
  LaserScannerModel laser;
  laser.azimuth_step_deg = 1.0;
  laser.elevation_step_deg = 1.0;
  laser.elevation_min_deg = -90.0;
  laser.min_range = 0.1;
  return laser;
}

struct Moments {
  double mean = 0.0, sd = 0.0;
};

Moments moments(const std::vector<double>& values) {
  Moments m;
  for (const double v : values) m.mean += v;
  m.mean /= static_cast<double>(values.size());
  for (const double v : values) m.sd += (v - m.mean) * (v - m.mean);
  m.sd = std::sqrt(m.sd / static_cast<double>(values.size() - 1));
  return m;
}

TEST(SensorModel, LaserGridCountsTheStepsOfItsWindow) {
  LaserScannerModel laser;            // 0.2 degrees, a full turn, elevation -60..90
  EXPECT_EQ(laser.columns(), 1800u);  // 360 / 0.2, the full turn not measured twice
  EXPECT_EQ(laser.rows(), 751u);      // 150 / 0.2 + 1: both ends of the window
  laser.azimuth_min_deg = -45.0;
  laser.azimuth_max_deg = 45.0;
  EXPECT_EQ(laser.columns(), 451u);
  EXPECT_DOUBLE_EQ(laser.elevation_deg(750), 90.0);
}

TEST(SensorModel, DisparityStepsAreTheKinectsWorkedByHand) {
  const DepthCameraModel kinect;  // 580 px x 0.075 m = 43.5 px m; 1/8 px steps
  // z = 2: d = 21.75 px = 174 steps exactly; 2.005 m rounds to the same step.
  EXPECT_DOUBLE_EQ(kinect.quantised_depth(2.0), 2.0);
  EXPECT_DOUBLE_EQ(kinect.quantised_depth(2.005), 2.0);
  // The next step away: 173 steps, 43.5 / (173 / 8) = 2.011561 m.
  EXPECT_NEAR(kinect.quantised_depth(2.008), 43.5 / (173 * 0.125), 1e-12);
  EXPECT_NEAR(kinect.depth_step(2.0), 43.5 / (173 * 0.125) - 2.0, 1e-12);  // 11.6 mm
  EXPECT_NEAR(kinect.depth_step(3.0), 43.5 / (115 * 0.125) - 3.0, 1e-12);  // 26.1 mm
  EXPECT_NEAR(kinect.depth_sigma(3.0), 0.0012 + 0.0019 * 2.6 * 2.6, 1e-15);
}

TEST(SensorModel, ModelsNoSensorHasAreRefused) {
  LaserScannerModel laser;
  laser.elevation_min_deg = 10.0;
  laser.elevation_max_deg = 5.0;
  EXPECT_THROW(validate(laser), std::invalid_argument);
  DepthCameraModel camera;
  camera.min_depth = 9.0;
  EXPECT_THROW(validate(camera), std::invalid_argument);
}

TEST(VirtualScanner, GroupsNameClassesAndInstances) {
  EXPECT_EQ(class_of_group("chair_3"), "chair");
  EXPECT_EQ(class_of_group("wall"), "wall");
  EXPECT_EQ(class_of_group("book_case_12"), "book_case");
  EXPECT_EQ(class_of_group("x_"), "x_");
  EXPECT_EQ(class_of_group("x_2b"), "x_2b");
}

TEST(VirtualScanner, NoiseFreeLaserReturnsLieOnTheMeshAndEveryBeamIsCounted) {
  const TriangleMesh mesh = room_with_box();
  SimulationOptions options;
  options.noise = false;
  const SimulatedScan scan = simulate_scan(mesh, {{"s1", {2, 2, 1.5}}}, coarse_laser(), options);
  const LaserScannerModel laser = coarse_laser();
  const BeamCounts& c = scan.counts;
  EXPECT_EQ(c.beams, laser.columns() * laser.rows());
  EXPECT_EQ(c.beams, c.returns + c.no_hit + c.out_of_range + c.grazing);
  EXPECT_EQ(c.no_hit, 0u);  // a closed room
  ASSERT_EQ(scan.cloud.size(), c.returns);
  scan.cloud.validate();
  for (std::size_t i = 0; i < scan.cloud.size(); ++i) {
    const Eigen::Vector3f& p = scan.cloud.positions[i];
    ASSERT_LT((p - scan.true_points[i]).norm(), 1e-4f) << i;
    // On the room's walls or the box: one coordinate at a wall's plane.
    const bool on_room = std::abs(p.x()) < 1e-4f || std::abs(p.x() - 6) < 1e-4f ||
                         std::abs(p.y()) < 1e-4f || std::abs(p.y() - 4) < 1e-4f ||
                         std::abs(p.z()) < 1e-4f || std::abs(p.z() - 3) < 1e-4f;
    const bool on_box = p.x() > 4 - 1e-4f && p.x() < 5 + 1e-4f && p.y() > 1 - 1e-4f &&
                        p.y() < 2 + 1e-4f && p.z() < 1 + 1e-4f;
    ASSERT_TRUE(on_room || on_box) << p.transpose();
    // The label says which (where the box stands on the floor, either).
    if (on_box != on_room) {
      EXPECT_EQ(scan.cloud.class_names[scan.cloud.labels[i]], on_box ? "table" : "room");
    }
  }
  EXPECT_EQ(scan.cloud.stations.size(), 1u);
  EXPECT_EQ(scan.cloud.stations[0].frame.width, laser.columns());
  EXPECT_EQ(scan.cloud.stations[0].frame.height, laser.rows());
}

TEST(VirtualScanner, RangeNoiseHasItsSigmaAlongTheBeamOnly) {
  LaserScannerModel laser = coarse_laser();
  laser.range_noise = 0.002;
  laser.range_noise_share = 0.001;  // sigma = 0.002 + 0.001 r
  const Eigen::Vector3d origin(2, 2, 1.5);
  const SimulatedScan scan = simulate_scan(room_with_box(), {{"s1", origin}}, laser);
  std::vector<double> standardised, across;
  for (std::size_t i = 0; i < scan.cloud.size(); ++i) {
    const Eigen::Vector3d truth = scan.true_points[i].cast<double>();
    const Eigen::Vector3d measured = scan.cloud.positions[i].cast<double>();
    const double range = (truth - origin).norm();
    const Eigen::Vector3d beam = (truth - origin) / range;
    const double error = (measured - origin).dot(beam) - range;
    standardised.push_back(error / laser.range_sigma(range));
    across.push_back(((measured - origin) - (measured - origin).dot(beam) * beam).norm());
  }
  const Moments m = moments(standardised);
  ASSERT_GT(standardised.size(), 40000u);
  EXPECT_NEAR(m.mean, 0.0, 0.02);
  EXPECT_NEAR(m.sd, 1.0, 0.02);
  EXPECT_LT(*std::max_element(across.begin(), across.end()), 1e-5);
}

TEST(VirtualScanner, TheSameSeedGivesTheSameCloudOnAnyNumberOfThreads) {
  const TriangleMesh mesh = room_with_box();
  const std::vector<ScannerStation> stations{{"a", {2, 2, 1.5}}, {"b", {5, 3, 2}}};
  SimulationOptions one, two, other;
  one.threads = 1;
  two.threads = 2;
  other.seed = 2;
  const SimulatedScan a = simulate_scan(mesh, stations, coarse_laser(), one);
  const SimulatedScan b = simulate_scan(mesh, stations, coarse_laser(), two);
  const SimulatedScan c = simulate_scan(mesh, stations, coarse_laser(), other);
  EXPECT_EQ(a.cloud.positions, b.cloud.positions);
  EXPECT_EQ(a.cloud.station_ids, b.cloud.station_ids);
  ASSERT_EQ(a.cloud.size(), c.cloud.size());
  EXPECT_NE(a.cloud.positions, c.cloud.positions);
  EXPECT_EQ(a.per_station.size(), 2u);
  EXPECT_EQ(a.per_station[0].returns + a.per_station[1].returns, a.cloud.size());
}

TEST(VirtualScanner, AWallHidesWhatStandsBehindIt) {
  TriangleMesh mesh;
  add_box(mesh, {0, 0, 0}, {10, 4, 3}, "room", 2);
  // A wall across the room at x = 5 with a 1 m gap at y in [3, 4], and a box
  // behind it that the gap cannot show from x = 1.
  add_quad(mesh, {5, 0, 0}, {0, 3, 0}, {0, 0, 3}, "wall_1");
  add_box(mesh, {7, 0.5, 0}, {8, 1.5, 1}, "hidden_1");
  add_box(mesh, {2, 0.5, 0}, {3, 1.5, 1}, "seen_1");
  const SimulatedScan scan = simulate_scan(mesh, {{"s", {1, 1, 0.5}}}, coarse_laser());
  std::set<std::string> classes;
  for (const auto label : scan.cloud.labels) classes.insert(scan.cloud.class_names[label]);
  EXPECT_EQ(classes.count("seen"), 1u);
  EXPECT_EQ(classes.count("wall"), 1u);
  EXPECT_EQ(classes.count("hidden"), 0u);
  // And the part of the room behind the wall the gap shows is really there.
  std::size_t beyond = 0;
  for (const auto& p : scan.true_points) beyond += p.x() > 5.01f ? 1 : 0;
  EXPECT_GT(beyond, 0u);
}

TEST(VirtualScanner, ReturnsBeyondTheIncidenceLimitAreDropped) {
  SimulationOptions options;
  options.max_incidence_deg = 60.0;
  const Eigen::Vector3d origin(3, 2, 1.5);
  const SimulatedScan scan =
      simulate_scan(room_with_box(), {{"s", origin}}, coarse_laser(), options);
  EXPECT_GT(scan.counts.grazing, 1000u);
  for (std::size_t i = 0; i < scan.cloud.size(); ++i) {
    const Eigen::Vector3f beam = (scan.true_points[i] - origin.cast<float>()).normalized();
    ASSERT_GE(-beam.dot(scan.true_normals[i]), std::cos(60.0 * std::acos(-1.0) / 180.0) - 1e-5)
        << i;
  }
}

TEST(VirtualScanner, ADivergentBeamMixesEchoesAtADepthEdge) {
  // A plate 1 m in front of a wall 1.2 m behind it: beams across its edge
  // see both, within the echo window, and report a range between the two.
  TriangleMesh mesh;
  add_quad(mesh, {2, -5, -5}, {0, 10, 0}, {0, 0, 10}, "wall");
  add_quad(mesh, {0.8, -5, -5}, {0, 5, 0}, {0, 0, 10}, "plate");  // y < 0
  LaserScannerModel laser;
  laser.azimuth_min_deg = -10;
  laser.azimuth_max_deg = 10;
  laser.elevation_min_deg = -1;
  laser.elevation_max_deg = 1;
  laser.azimuth_step_deg = 0.05;
  laser.elevation_step_deg = 1;
  laser.min_range = 0.1;
  laser.range_noise = 0.0;
  laser.beam_divergence_mrad = 20.0;  // a footprint of 16 mm at 0.8 m
  laser.beam_samples = 19;
  laser.echo_window = 2.0;
  const SimulatedScan wide = simulate_scan(mesh, {{"s", {0, 0, 0}}}, laser);
  laser.echo_window = 0.5;
  const SimulatedScan separated = simulate_scan(mesh, {{"s", {0, 0, 0}}}, laser);
  const auto mixed = [](const SimulatedScan& scan) {
    std::size_t count = 0;
    for (const auto& p : scan.cloud.positions) count += p.x() > 0.81f && p.x() < 1.99f ? 1 : 0;
    return count;
  };
  EXPECT_GT(mixed(wide), 0u);
  EXPECT_EQ(mixed(separated), 0u);  // 1.2 m apart: two echoes, the first one kept
}

TEST(VirtualScanner, ADepthCameraReportsTheStepOfItsDisparity) {
  // A wall 2.003 m in front of the camera: every pixel's disparity rounds to
  // 174 eighths of a pixel, so every depth reads 2.0 m (hand-worked above).
  TriangleMesh mesh;
  add_quad(mesh, {2.003, -5, -5}, {0, 10, 0}, {0, 0, 10}, "wall");
  DepthCameraModel camera;
  camera.width = 64;
  camera.height = 48;
  camera.cx = 31.5;
  camera.cy = 23.5;
  camera.depth_noise_a = camera.depth_noise_b = 0.0;
  ScannerStation station{"kinect", {0, 0, 0}, camera_looking_at({0, 0, 0}, {1, 0, 0}, {0, 0, 1})};
  const SimulatedScan scan = simulate_scan(mesh, {station}, camera);
  ASSERT_EQ(scan.cloud.size(), 64u * 48u);
  for (const auto& p : scan.cloud.positions) ASSERT_NEAR(p.x(), 2.0, 1e-6);
  scan.cloud.validate();  // an organised frame with one pixel a point
  EXPECT_TRUE(scan.cloud.sensor.organised());
  // Image up is +z: row 0 looks up, column 0 looks to +y (the camera's left),
  // 23.5 and 31.5 pixels off the axis at 580 px, at a depth of 2 m.
  EXPECT_NEAR(scan.cloud.positions.front().z(), 2.0 * 23.5 / 580.0, 1e-5);
  EXPECT_NEAR(scan.cloud.positions.front().y(), 2.0 * 31.5 / 580.0, 1e-5);
}

TEST(VirtualScanner, DepthNoiseHasTheSigmaOfItsFormula) {
  TriangleMesh mesh;
  add_quad(mesh, {3, -10, -10}, {0, 20, 0}, {0, 0, 20}, "wall");
  DepthCameraModel camera;
  camera.disparity_step = 0.0;
  ScannerStation station{"kinect", {0, 0, 0}, camera_looking_at({0, 0, 0}, {1, 0, 0}, {0, 0, 1})};
  const SimulatedScan scan = simulate_scan(mesh, {station}, camera);
  std::vector<double> standardised;
  for (const auto& p : scan.cloud.positions) {
    standardised.push_back((p.x() - 3.0) / camera.depth_sigma(3.0));
  }
  const Moments m = moments(standardised);
  ASSERT_GT(standardised.size(), 300000u);
  EXPECT_NEAR(m.mean, 0.0, 0.01);
  EXPECT_NEAR(m.sd, 1.0, 0.01);
}

}  // namespace
}  // namespace occlusion
