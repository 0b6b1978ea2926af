// What candidate stations see, judged against the truth: the furnished room's
// mesh traced exactly (clouds sampled from it), -moc's own per-viewpoint
// areas (mesh samples), and hand-worked limits.
#include "occlusion/analysis/station_visibility.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "occlusion/analysis/surfel_estimation.hpp"
#include "support/mesh_truth.hpp"

namespace occlusion {
namespace {

using testing::furnished_room;
using testing::SampledCloud;

// Inside the room: above the furniture, low among it (the floor at grazing
// angles), in a corner by the table, in the open at tripod height. Near a
// wall: 1 m and 0.6 m from one (most of it seen at grazing angles). Outside:
// behind the wall x = 6, beside the crate.
const std::vector<Eigen::Vector3d> kInside = {
    {3.0, 2.5, 2.6}, {2.2, 3.4, 0.35}, {1.0, 1.0, 1.6}, {4.0, 3.2, 1.5}, {2.5, 4.3, 1.5}};
const std::vector<Eigen::Vector3d> kNearWall = {{5.0, 1.5, 1.2}, {5.3, 0.6, 1.5}};
const Eigen::Vector3d kOutside(6.6, 2.5, 1.5);

// The furnished room sampled at random, 1000 points per square metre, and its
// discs as -fscan estimates them by default.
struct SampledRoom {
  TriangleMesh mesh = furnished_room();
  SampledCloud sampled = testing::sample_room(mesh, 1000.0, 1);
  SurfelEstimate surfels = estimate_surfels(sampled.cloud, SurfelOptions{});
  ScanOptions options() const {
    ScanOptions o;
    o.surfels = &surfels;
    return o;
  }
  const std::string& group_of(std::size_t point) const {
    return mesh.group_names[mesh.face_group[sampled.face[point]]];
  }
};

const SampledRoom& sampled_room() {
  static const SampledRoom room;
  return room;
}

std::vector<double> ones(std::size_t n) {
  return std::vector<double>(n, 1.0);
}

std::vector<bool> row(const CoverageMatrix& matrix, std::size_t c) {
  std::vector<bool> bits(matrix.targets());
  for (std::size_t t = 0; t < bits.size(); ++t) bits[t] = matrix.seen(c, t);
  return bits;
}

TEST(StationVisibility, CloudRowsAgreeWithTheMeshFromEachCandidate) {
  const SampledRoom& room = sampled_room();
  std::vector<Eigen::Vector3d> candidates = kInside;
  candidates.insert(candidates.end(), kNearWall.begin(), kNearWall.end());
  candidates.push_back(kOutside);
  const PointCloud& cloud = room.sampled.cloud;
  const CoverageMatrix matrix =
      cloud_station_coverage(cloud, candidates, ones(cloud.size()), room.options(), {});
  ASSERT_EQ(matrix.candidates(), candidates.size());
  ASSERT_EQ(matrix.targets(), cloud.size());
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const std::vector<std::uint8_t> truth =
        testing::mesh_visibility(room.mesh, room.sampled, candidates[c]);
    std::size_t same = 0, visible = 0, kept = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      same += matrix.seen(c, i) == (truth[i] != 0);
      visible += truth[i];
      kept += truth[i] && matrix.seen(c, i);
    }
    const double n = static_cast<double>(cloud.size());
    // Near a wall the -fscan rule loses a little more of it, seen at grazing
    // angles (96.5 % and 96.9 % agree there).
    const bool near_wall = c >= kInside.size() && c < kInside.size() + kNearWall.size();
    EXPECT_GE(same / n, near_wall ? 0.96 : 0.97) << "candidate " << c;
    EXPECT_GE(static_cast<double>(kept) / static_cast<double>(visible), 0.97) << "candidate " << c;
    EXPECT_NEAR(matrix.seen_weight(c), static_cast<double>(visible), 0.02 * n) << "candidate " << c;
  }
}

TEST(StationVisibility, AWallHidesWhatIsBehindIt) {
  const SampledRoom& room = sampled_room();
  const PointCloud& cloud = room.sampled.cloud;
  std::vector<Eigen::Vector3d> candidates = kInside;
  candidates.push_back(kOutside);
  const CoverageMatrix matrix =
      cloud_station_coverage(cloud, candidates, ones(cloud.size()), room.options(), {});
  const std::size_t outside = kInside.size();
  // The discs close 99 % of a surface (kDefaultDiscCoverage): a ray through
  // a wall finds a gap about once in a hundred, never much more.
  std::size_t crate = 0, crate_seen_inside = 0, crate_seen_outside = 0;
  std::size_t in_room = 0, room_seen_outside = 0, room_seen_inside = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (room.group_of(i) == "clutter") {
      ++crate;
      for (std::size_t c = 0; c < kInside.size(); ++c) crate_seen_inside += matrix.seen(c, i);
      crate_seen_outside += matrix.seen(outside, i);
      continue;
    }
    // Leave out the wall x = 6 itself: one sheet of points, seen from both sides.
    if (cloud.positions[i].x() > 5.95f) continue;
    ++in_room;
    room_seen_outside += matrix.seen(outside, i);
    room_seen_inside += matrix.seen(0, i);
  }
  ASSERT_GT(crate, 100u);
  EXPECT_LT(crate_seen_inside, crate * kInside.size() / 100);
  EXPECT_LT(room_seen_outside, in_room / 100);
  EXPECT_GT(crate_seen_outside, crate / 3);
  // A station above the furniture sees most of its own room.
  EXPECT_GT(room_seen_inside, in_room * 8 / 10);
}

TEST(StationVisibility, CloudRowIsWhatScanSees) {
  // The planning and -fscan apply one rule: with no limit and every weight
  // set, a candidate's row is scan_cloud's answer from that viewpoint.
  const SampledRoom& room = sampled_room();
  const PointCloud& cloud = room.sampled.cloud;
  const CoverageMatrix matrix =
      cloud_station_coverage(cloud, {kInside[1]}, ones(cloud.size()), room.options(), {});
  const ScanResult scan = scan_cloud(cloud, {kInside[1]}, room.options());
  std::size_t seen = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    ASSERT_EQ(matrix.seen(0, i), scan.visible_count[i] > 0) << i;
    seen += matrix.seen(0, i);
  }
  EXPECT_EQ(seen, scan.visible_points);
}

TEST(StationVisibility, SameMatrixWhateverTheThreads) {
  // One thread fills whole rows, one candidate at a time; with more threads
  // than a third of the candidates, each candidate's blocks go to all.
  const SampledRoom& room = sampled_room();
  const PointCloud& cloud = room.sampled.cloud;
  const std::vector<Eigen::Vector3d> candidates = {kInside[0], kInside[1], kOutside};
  ScanOptions options = room.options();
  options.threads = 1;
  const CoverageMatrix one =
      cloud_station_coverage(cloud, candidates, ones(cloud.size()), options, {});
  options.threads = 2;
  const CoverageMatrix two =
      cloud_station_coverage(cloud, candidates, ones(cloud.size()), options, {});
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    EXPECT_EQ(row(one, c), row(two, c)) << "candidate " << c;
  }
}

TEST(StationVisibility, OneOctreeAnswersAnyCandidatesLater) {
  // Built once, asked a row at a time (a viewer dragging a station) or for
  // some candidates only: the same rows as the whole matrix.
  const SampledRoom& room = sampled_room();
  const PointCloud& cloud = room.sampled.cloud;
  const ScanOptions options = room.options();
  const CloudStationVisibility visibility(cloud, ones(cloud.size()), options, {});
  const CoverageMatrix all = visibility.coverage(kInside);
  for (std::size_t c = 0; c < kInside.size(); ++c) {
    EXPECT_EQ(row(visibility.coverage({kInside[c]}), 0), row(all, c)) << "candidate " << c;
  }
  const CoverageMatrix some = visibility.coverage({kInside[3], kInside[1]});
  EXPECT_EQ(row(some, 0), row(all, 3));
  EXPECT_EQ(row(some, 1), row(all, 1));

  const TriangleMesh& mesh = room.mesh;
  const MeshSamples samples = sample_mesh(mesh, 20.0, 1);
  const MeshOcclusionOptions mesh_options;
  const MeshStationVisibility mesh_visibility(mesh, samples, ones(samples.size()), mesh_options,
                                              {});
  const CoverageMatrix mesh_all = mesh_visibility.coverage(kInside);
  EXPECT_EQ(row(mesh_visibility.coverage({kInside[2]}), 0), row(mesh_all, 2));
  EXPECT_EQ(mesh_visibility.intervisibility({kInside[2], kInside[3], kOutside}),
            mesh_candidate_intervisibility(mesh, {kInside[2], kInside[3], kOutside}, mesh_options));
}

TEST(StationVisibility, ZeroWeightTargetsAreNeverSet) {
  const SampledRoom& room = sampled_room();
  const PointCloud& cloud = room.sampled.cloud;
  std::vector<double> weight = ones(cloud.size());
  std::size_t ceiling = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (room.group_of(i) == "ceiling") {
      weight[i] = 0.0;
      ++ceiling;
    }
  }
  const CoverageMatrix all =
      cloud_station_coverage(cloud, {kInside[0]}, ones(cloud.size()), room.options(), {});
  const CoverageMatrix weighted =
      cloud_station_coverage(cloud, {kInside[0]}, weight, room.options(), {});
  std::size_t ceiling_seen = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (weight[i] == 0.0) {
      ceiling_seen += all.seen(0, i);
      EXPECT_FALSE(weighted.seen(0, i)) << i;
    } else {
      EXPECT_EQ(weighted.seen(0, i), all.seen(0, i)) << i;
    }
  }
  // Seen when weighed: the zero weight alone keeps them out.
  EXPECT_GT(ceiling_seen, ceiling * 9 / 10);
  EXPECT_DOUBLE_EQ(weighted.total_weight(), static_cast<double>(cloud.size() - ceiling));
}

// Isolated targets, far enough apart that none hides another: what the limits
// alone decide.
PointCloud isolated(const std::vector<Eigen::Vector3f>& positions) {
  PointCloud cloud;
  cloud.positions = positions;
  return cloud;
}

ScanOptions small_spheres() {
  ScanOptions options;
  options.point_radius = 0.01;
  return options;
}

TEST(StationVisibility, MaxRangeKeepsTargetsUpToItsDistance) {
  // 4.9 and 5.1 m away, and exactly 5 (kept: only farther is excluded).
  const PointCloud cloud = isolated({{4.9f, 0, 0}, {0, 5.1f, 0}, {0, 0, -5.0f}});
  const std::vector<Eigen::Vector3d> station = {Eigen::Vector3d::Zero()};
  const auto none = cloud_station_coverage(cloud, station, ones(3), small_spheres(), {});
  EXPECT_EQ(row(none, 0), std::vector<bool>({true, true, true}));
  StationLimits limits;
  limits.max_range = 5.0;
  const auto limited = cloud_station_coverage(cloud, station, ones(3), small_spheres(), limits);
  EXPECT_EQ(row(limited, 0), std::vector<bool>({true, false, true}));
}

TEST(StationVisibility, ElevationLimitsAreAnglesAboveThePlaneNormalToUp) {
  // At +30, 0 and -30 degrees of elevation, 2 m away.
  const float c = 2.0f * std::cos(static_cast<float>(M_PI) / 6.0f);
  const PointCloud cloud = isolated({{c, 0, 1.0f}, {0, 2.0f, 0}, {-c, 0, -1.0f}});
  const std::vector<Eigen::Vector3d> station = {Eigen::Vector3d::Zero()};
  StationLimits limits;
  limits.min_elevation_deg = -10.0;
  limits.max_elevation_deg = 45.0;
  auto matrix = cloud_station_coverage(cloud, station, ones(3), small_spheres(), limits);
  EXPECT_EQ(row(matrix, 0), std::vector<bool>({true, true, false}));
  limits.min_elevation_deg = -90.0;
  limits.max_elevation_deg = 20.0;
  matrix = cloud_station_coverage(cloud, station, ones(3), small_spheres(), limits);
  EXPECT_EQ(row(matrix, 0), std::vector<bool>({false, true, true}));
  // Up along -x: the first point lies 60 degrees below that plane's level
  // (its elevation is asin(-cos 30) = -60), the third 60 above.
  limits.up = {-3.0, 0.0, 0.0};  // any length
  limits.min_elevation_deg = -50.0;
  limits.max_elevation_deg = 90.0;
  matrix = cloud_station_coverage(cloud, station, ones(3), small_spheres(), limits);
  EXPECT_EQ(row(matrix, 0), std::vector<bool>({false, true, true}));
}

// Discs of radius 1 cm with the given normals (zero: a sphere), as
// estimate_surfels would hand them over.
SurfelEstimate hand_made_discs(const PointCloud& cloud,
                               const std::vector<Eigen::Vector3f>& normals) {
  SurfelEstimate estimate;
  const std::vector<float> radii(cloud.size(), 0.01f);
  estimate.surfels = make_surfels(cloud.positions, normals, radii);
  estimate.thickness.assign(cloud.size(), 0.001f);
  estimate.stats.points = cloud.size();
  estimate.stats.radius_quantile_10 = estimate.stats.radius_median =
      estimate.stats.radius_quantile_90 = 0.01;
  return estimate;
}

TEST(StationVisibility, IncidenceLimitIsTheAngleFromTheSurfaceNormal) {
  // A station 1 m above a floor. Floor discs where its ray meets the floor
  // 60 and 80 degrees from the normal (tan 60 and tan 80 m away), one at 60
  // facing down (surfaces are two-sided), and a sphere at 80 (no normal: the
  // limit does not apply to it).
  const float d60 = std::tan(static_cast<float>(M_PI) / 3.0f);
  const float d80 = std::tan(80.0f * static_cast<float>(M_PI) / 180.0f);
  const PointCloud cloud = isolated({{d60, 0, 0}, {0, d80, 0}, {-d60, 0, 0}, {0, -d80, 0}});
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  const SurfelEstimate discs = hand_made_discs(cloud, {up, up, -up, Eigen::Vector3f::Zero()});
  ScanOptions options;
  options.surfels = &discs;
  const std::vector<Eigen::Vector3d> station = {{0.0, 0.0, 1.0}};
  const auto none = cloud_station_coverage(cloud, station, ones(4), options, {});
  EXPECT_EQ(row(none, 0), std::vector<bool>({true, true, true, true}));
  StationLimits limits;
  limits.max_incidence_deg = 70.0;
  auto matrix = cloud_station_coverage(cloud, station, ones(4), options, limits);
  EXPECT_EQ(row(matrix, 0), std::vector<bool>({true, false, true, true}));
  limits.max_incidence_deg = 55.0;
  matrix = cloud_station_coverage(cloud, station, ones(4), options, limits);
  EXPECT_EQ(row(matrix, 0), std::vector<bool>({false, false, false, true}));
  limits.max_incidence_deg = 85.0;
  matrix = cloud_station_coverage(cloud, station, ones(4), options, limits);
  EXPECT_EQ(row(matrix, 0), std::vector<bool>({true, true, true, true}));
}

TEST(StationVisibility, CandidatesSeeEachOtherSymmetricallyAndNotThroughAWall) {
  const SampledRoom& room = sampled_room();
  // Two stations in the room with a clear line between them (over the table,
  // past the board's end), one outside.
  const std::vector<Eigen::Vector3d> candidates = {kInside[2], kInside[3], kOutside};
  const std::vector<std::uint8_t> expected = {1, 1, 0, 1, 1, 0, 0, 0, 1};
  EXPECT_EQ(cloud_candidate_intervisibility(room.sampled.cloud, candidates, room.options()),
            expected);
  EXPECT_EQ(mesh_candidate_intervisibility(room.mesh, candidates, MeshOcclusionOptions{}),
            expected);
}

TEST(StationVisibility, MeshRowsWeighWhatMocSeesFromEachCandidate) {
  // -moc's per-viewpoint visible area is the weight of a row whose samples
  // weigh their face's area shared among its samples.
  const TriangleMesh mesh = furnished_room();
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 40.0;
  options.seed = 5;
  const MeshSamples samples = sample_mesh(mesh, options.samples_per_unit_area, options.seed);
  std::vector<double> weight(samples.size());
  for (std::size_t s = 0; s < samples.size(); ++s) {
    weight[s] =
        mesh.face_area(samples.face[s]) / static_cast<double>(samples.count_on(samples.face[s]));
  }
  std::vector<Eigen::Vector3d> candidates = kInside;
  candidates.push_back(kOutside);
  const CoverageMatrix matrix =
      mesh_station_coverage(mesh, samples, candidates, weight, options, {});
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const MeshOcclusionResult moc = compute_mesh_occlusion(mesh, {candidates[c]}, options);
    EXPECT_NEAR(matrix.seen_weight(c), moc.viewpoints[0].visible_area, 1e-9 * moc.total_area)
        << "candidate " << c;
  }
  // And the crate: never from inside, and from outside nothing but it and the
  // wall's outer side.
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const std::string& group = mesh.group_names[mesh.face_group[samples.face[s]]];
    for (std::size_t c = 0; c < kInside.size(); ++c) {
      if (group == "clutter") {
        EXPECT_FALSE(matrix.seen(c, s)) << s;
      }
    }
    if (group != "clutter" && samples.points[s].x() < 5.95) {
      EXPECT_FALSE(matrix.seen(kInside.size(), s)) << s;
    }
  }
}

TEST(StationVisibility, MeshIncidenceUsesTheFaceNormal) {
  // A 20 x 20 m floor, a station 1 m above its centre: a sample is seen at
  // most 70 degrees from the normal, i.e. within tan 70 = 2.75 m horizontally.
  TriangleMesh floor;
  testing::add_quad(floor, {-10, -10, 0}, {20, 0, 0}, {0, 20, 0}, "floor");
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 10.0;
  const MeshSamples samples = sample_mesh(floor, options.samples_per_unit_area, options.seed);
  StationLimits limits;
  limits.max_incidence_deg = 70.0;
  const CoverageMatrix matrix = mesh_station_coverage(floor, samples, {{0.0, 0.0, 1.0}},
                                                      ones(samples.size()), options, limits);
  const double radius = std::tan(70.0 * M_PI / 180.0);
  std::size_t near = 0;
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const double distance = samples.points[s].head<2>().norm();
    if (std::abs(distance - radius) < 1e-6) continue;
    EXPECT_EQ(matrix.seen(0, s), distance < radius) << samples.points[s].transpose();
    near += distance < radius;
  }
  EXPECT_GT(near, 100u);
}

TEST(StationVisibility, CancelStopsTheTracing) {
  const PointCloud cloud = isolated({{1, 0, 0}, {0, 1, 0}});
  std::atomic<bool> cancel{false};
  Progress progress;
  progress.cancel = &cancel;
  progress.report = [&](const std::string& stage, double) {
    if (stage == "tracing") cancel = true;
  };
  EXPECT_THROW(cloud_station_coverage(cloud, {{0, 0, 0}}, ones(2), small_spheres(), {}, progress),
               Cancelled);
  cancel = false;
  const TriangleMesh mesh = furnished_room();
  const MeshSamples samples = sample_mesh(mesh, 1.0, 0);
  EXPECT_THROW(mesh_station_coverage(mesh, samples, {{3, 2, 1}}, ones(samples.size()),
                                     MeshOcclusionOptions{}, {}, progress),
               Cancelled);
}

// A cancel takes effect within a block of rays, whether few candidates share
// the threads or each thread traces its own: it was checked (and progress,
// which is where Python polls Ctrl-C, reported) once per candidate, whose
// rays to a million targets take seconds (issue 44, 2.10). The cancel comes
// in the first report of some tracing done; nothing is reported after it.
TEST(StationVisibility, CancelTakesEffectWithinASmallShareOfTheTracing) {
  TriangleMesh floor;
  testing::add_quad(floor, {0, 0, 0}, {10, 0, 0}, {0, 10, 0}, "floor");
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 6000.0;  // 600,000 targets
  options.threads = 2;
  const MeshSamples samples = sample_mesh(floor, options.samples_per_unit_area, options.seed);
  // One candidate: its blocks on both threads; four: a candidate per thread.
  for (const std::size_t count : {std::size_t{1}, std::size_t{4}}) {
    const std::vector<Eigen::Vector3d> candidates(count, Eigen::Vector3d(5, 5, 1));
    std::atomic<bool> cancel{false};
    double at_cancel = -1.0, after_cancel = -1.0;
    Progress progress;
    progress.cancel = &cancel;
    progress.report = [&](const std::string& stage, double fraction) {
      if (stage != "tracing" || fraction == 0.0) return;
      if (cancel) {
        after_cancel = std::max(after_cancel, fraction);
        return;
      }
      at_cancel = fraction;
      cancel = true;
    };
    EXPECT_THROW(mesh_station_coverage(floor, samples, candidates, ones(samples.size()), options,
                                       {}, progress),
                 Cancelled)
        << count;
    EXPECT_GT(at_cancel, 0.0) << count;
    EXPECT_LT(at_cancel, 0.2) << count << " candidates: a cancel waited for whole candidates";
    EXPECT_EQ(after_cancel, -1.0) << count << " candidates: traced on after the cancel";
  }
}

template <class Call>
void expect_refused(const Call& call, const std::string& words) {
  try {
    call();
    ADD_FAILURE() << "accepted; expected a refusal mentioning '" << words << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(StationVisibility, RefusesBadInputWithAClearMessage) {
  const PointCloud cloud = isolated({{1, 0, 0}, {0, 1, 0}});
  const ScanOptions options = small_spheres();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_refused([&] { cloud_station_coverage(cloud, {}, ones(2), options, {}); },
                 "no candidate stations");
  expect_refused(
      [&] {
        cloud_station_coverage(cloud, {{0, 0, 0}, {nan, 0, 0}}, ones(2), options, {});
      },
      "candidate 1 is not finite");
  expect_refused(
      [&] {
        cloud_station_coverage(cloud, {{0, 0, 0}}, ones(3), options, {});
      },
      "3 target weights for 2 points");
  expect_refused(
      [&] {
        cloud_station_coverage(cloud, {{0, 0, 0}}, {1.0, -1.0}, options, {});
      },
      "negative");
  StationLimits limits;
  limits.max_incidence_deg = 95.0;
  expect_refused(
      [&] {
        cloud_station_coverage(cloud, {{0, 0, 0}}, ones(2), options, limits);
      },
      "max_incidence_deg");
  limits = {};
  limits.min_elevation_deg = 30.0;
  limits.max_elevation_deg = 10.0;
  expect_refused(
      [&] {
        cloud_station_coverage(cloud, {{0, 0, 0}}, ones(2), options, limits);
      },
      "is above max_elevation_deg");
  limits = {};
  limits.up = Eigen::Vector3d::Zero();
  expect_refused(
      [&] {
        cloud_station_coverage(cloud, {{0, 0, 0}}, ones(2), options, limits);
      },
      "up axis");
  limits = {};
  limits.max_range = -1.0;
  expect_refused(
      [&] {
        cloud_station_coverage(cloud, {{0, 0, 0}}, ones(2), options, limits);
      },
      "max_range");
  ScanOptions windowed = options;
  windowed.field_of_view = SphericalFieldOfView{};
  expect_refused(
      [&] {
        cloud_station_coverage(cloud, {{0, 0, 0}}, ones(2), windowed, {});
      },
      "all the way round");
  expect_refused([&] { cloud_candidate_intervisibility(cloud, {}, options); },
                 "no candidate stations");

  const TriangleMesh mesh = furnished_room();
  const MeshSamples samples = sample_mesh(mesh, 1.0, 0);
  expect_refused(
      [&] {
        mesh_station_coverage(mesh, samples, {}, ones(samples.size()), MeshOcclusionOptions{}, {});
      },
      "no candidate stations");
  expect_refused(
      [&] {
        mesh_station_coverage(mesh, samples, {{3, 2, 1}}, ones(samples.size() + 1),
                              MeshOcclusionOptions{}, {});
      },
      "target weights for");
  expect_refused(
      [&] {
        mesh_candidate_intervisibility(mesh, {{nan, 0, 0}}, MeshOcclusionOptions{});
      },
      "candidate 0 is not finite");
}

}  // namespace
}  // namespace occlusion
