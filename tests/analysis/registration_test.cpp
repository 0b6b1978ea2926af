// Registration against the truth: two simulated scans of a furnished room,
// the second expressed in its own scanner's frame by a known pose, must come
// back to that pose from a perturbed start; the real tutorial pair of PCL
// must reach the same pose from perturbed starts; and pairs that cannot be
// registered are refused, never answered with a wrong pose.

#include "occlusion/analysis/registration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "occlusion/analysis/virtual_scanner.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/mesh_reader.hpp"

namespace occlusion {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Isometry3d pose_of(double yaw, const Eigen::Vector3d& translation, double tilt = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = translation;
  return pose;
}

double degrees_between(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / kPi;
}

PointCloud transformed(const PointCloud& cloud, const Eigen::Isometry3d& pose) {
  PointCloud out;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    out.positions.push_back((pose * cloud.original_position(i)).cast<float>());
  }
  return out;
}

// Every `stride`-th point: the tests' clouds thinned so each registration
// takes about a second.
PointCloud thinned(const PointCloud& cloud, std::size_t stride) {
  PointCloud out;
  for (std::size_t i = 0; i < cloud.size(); i += stride)
    out.positions.push_back(cloud.positions[i]);
  out.shift = cloud.shift;
  return out;
}

// Two scans of files/sample_room.obj (8 x 6 x 3 m, furnished) with 3 mm
// range noise from two stations; scan 2 is given in its own scanner's frame,
// which the known pose takes into the room's (scan 1's) frame.
struct SimulatedPair {
  PointCloud target, source;
  Eigen::Isometry3d truth;
};

const SimulatedPair& simulated_pair() {
  static const SimulatedPair pair = [] {
    const TriangleMesh mesh =
        read_mesh(std::string(OCCLUSION_SOURCE_DIR) + "/files/sample_room.obj");
    LaserScannerModel laser;
    laser.azimuth_step_deg = 0.8;
    laser.elevation_step_deg = 0.8;
    laser.range_noise = 0.003;
    SimulationOptions options;
    options.seed = 7;
    const auto scan_from = [&](const Eigen::Vector3d& position) {
      ScannerStation station;
      station.name = "station";
      station.position = position;
      return simulate_scan(mesh, {station}, laser, options).cloud;
    };
    SimulatedPair p;
    p.target = scan_from({2.0, 2.0, 1.4});
    // The second scanner stands at (5.5, 4, 1.6), turned 25 degrees and tilted 2.
    p.truth = pose_of(25.0 * kPi / 180.0, {5.5, 4.0, 1.6}, 2.0 * kPi / 180.0);
    p.source = transformed(scan_from({5.5, 4.0, 1.6}), p.truth.inverse());
    return p;
  }();
  return pair;
}

TEST(Registration, SimulatedScanComesBackToItsKnownPose) {
  const SimulatedPair& pair = simulated_pair();
  ASSERT_GT(pair.source.size(), 10000u);
  ASSERT_GT(pair.target.size(), 10000u);
  // Off by 0.05 rad (2.9 degrees) about z and (0.2, -0.15, 0.05) m.
  const Eigen::Isometry3d start = pair.truth * pose_of(0.05, {0.2, -0.15, 0.05});
  const RegistrationResult r = register_pair(pair.source, pair.target, start);
  EXPECT_TRUE(r.converged);
  // The range noise is 3 mm per point and tens of thousands of points pull
  // on the pose, so what remains is the two grids sampling the surfaces at
  // different spots: within 1 cm and 0.1 degrees of the truth.
  EXPECT_LT((r.refined.translation() - pair.truth.translation()).norm(), 0.01);
  EXPECT_LT(degrees_between(r.refined, pair.truth), 0.1);
  // The start was 2.9 degrees and 0.25 m off: the report says it moved that far back.
  EXPECT_NEAR(r.moved_rotation_deg, 0.05 * 180.0 / kPi, 0.2);
  EXPECT_GT(r.after.overlap, r.before.overlap);
  EXPECT_GT(r.after.overlap, 0.5);
  // The residual (to the target's local plane, within the evaluation
  // distance) falls to less than half the start's; what remains is surfaces
  // only one scan sees lying within that distance of another (furniture
  // edges, the floor under a table), not the 3 mm noise.
  EXPECT_LT(r.after.rms, 0.5 * r.before.rms);
  ASSERT_EQ(r.levels.size(), 3u);
  EXPECT_GT(r.levels.front().voxel, r.levels.back().voxel);
}

TEST(Registration, ScansThatDoNotMeetAreRefused) {
  const SimulatedPair& pair = simulated_pair();
  Eigen::Isometry3d start = pair.truth;
  start.translation() += Eigen::Vector3d(100.0, 0.0, 0.0);
  try {
    register_pair(pair.source, pair.target, start);
    FAIL() << "a pair 100 m apart was registered";
  } catch (const RegistrationRefused& refused) {
    EXPECT_NE(std::string(refused.what()).find("do not overlap"), std::string::npos)
        << refused.what();
    EXPECT_NE(std::string(refused.what()).find("initial pose"), std::string::npos);
  }
}

TEST(Registration, AStartTurnedHalfWayRoundIsRefused) {
  const SimulatedPair& pair = simulated_pair();
  const Eigen::Isometry3d start = pair.truth * pose_of(kPi, Eigen::Vector3d::Zero());
  try {
    const RegistrationResult r = register_pair(pair.source, pair.target, start);
    FAIL() << "registered from 180 degrees off, to a pose "
           << degrees_between(r.refined, pair.truth) << " degrees from the truth";
  } catch (const RegistrationRefused& refused) {
    // Whichever check caught it, the pose it reached is not the truth's
    // refinement, and the message says what to do.
    EXPECT_NE(std::string(refused.what()).find("initial pose"), std::string::npos)
        << refused.what();
  }
}

// PCL's NDT tutorial pair: the same room scanned from two positions.
struct TutorialPair {
  PointCloud target, source;
};

const TutorialPair& tutorial_pair() {
  static const TutorialPair pair = [] {
    const std::string dir = std::string(OCCLUSION_SOURCE_DIR) + "/files/pcl/";
    return TutorialPair{thinned(read_cloud(dir + "room_scan1.pcd"), 4),
                        thinned(read_cloud(dir + "room_scan2.pcd"), 4)};
  }();
  return pair;
}

// The tutorial's initial guess: 0.6931 rad about z, then (1.79387, 0.720047, 0).
Eigen::Isometry3d tutorial_guess(double extra_yaw = 0.0, const Eigen::Vector3d& extra = {0, 0, 0}) {
  return pose_of(0.6931 + extra_yaw, Eigen::Vector3d(1.79387, 0.720047, 0.0) + extra);
}

TEST(Registration, TutorialPairConvergesToOnePoseFromPerturbedGuesses) {
  const TutorialPair& pair = tutorial_pair();
  const RegistrationResult base = register_pair(pair.source, pair.target, tutorial_guess());
  EXPECT_TRUE(base.converged);
  EXPECT_GT(base.after.overlap, base.before.overlap + 0.1);
  // Smaller, though not by much: the start's residual counts only the points
  // already within the evaluation distance (about half of them), the refined
  // one's two thirds, and this old scanner's points scatter by centimetres.
  EXPECT_LT(base.after.rms, 0.85 * base.before.rms);
  // The true pose of the real pair is not known; a refinement worth the name
  // reaches the same pose from starts 0.05 rad and 0.2 m away on every axis
  // of the floor: within 1 cm and 0.05 degrees, a tenth of the finest level's voxel
  // (about 10 cm for the thinned scans) and its angle at 10 m.
  for (const double sign : {1.0, -1.0}) {
    const RegistrationResult r =
        register_pair(pair.source, pair.target,
                      tutorial_guess(sign * 0.05, sign * Eigen::Vector3d(0.2, -0.2, 0)));
    EXPECT_TRUE(r.converged);
    EXPECT_LT((r.refined.translation() - base.refined.translation()).norm(), 0.01) << sign;
    EXPECT_LT(degrees_between(r.refined, base.refined), 0.05) << sign;
  }
}

TEST(Registration, BadOptionsAreRefusedNamingThem) {
  const SimulatedPair& pair = simulated_pair();
  RegistrationOptions options;
  options.min_overlap = 0.0;
  EXPECT_THROW(register_pair(pair.source, pair.target, pair.truth, options), std::invalid_argument);
  EXPECT_EQ(parse_registration_method("ndt"), RegistrationMethod::kNdt);
  EXPECT_THROW(parse_registration_method("icp"), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
