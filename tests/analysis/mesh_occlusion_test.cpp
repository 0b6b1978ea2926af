#include "occlusion/analysis/mesh_occlusion.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "occlusion/analysis/mesh_sampling.hpp"
#include "support/scenes.hpp"

namespace occlusion {
namespace {

using testing::add_box;
using testing::add_quad;

// A closed room [0,4] x [0,4] x [0,3] (each face split into grid x grid
// quads), a square plate of side `side` at height 1 centred over (2, 2), and a
// point viewpoint at (2, 2, 2). By similar triangles the plate's shadow on the
// floor is a square of side side * 2 / (2 - 1), centred at (2, 2); nothing else
// is hidden (a ray from the viewpoint to a wall point below it would have to
// drop 1 m within side/2 horizontally of the centre, but walls are 2 m away).
const Eigen::Vector3d kLamp(2, 2, 2);
constexpr double kRoomArea = 2 * 16 + 4 * 12;

double shadow_area(double side) {
  return (2 * side) * (2 * side);
}
double total_area(double side) {
  return kRoomArea + side * side;
}

TriangleMesh room_with_plate(int grid = 8, double side = 1.0) {
  TriangleMesh mesh;
  add_box(mesh, {0, 0, 0}, {4, 4, 3}, "room", grid);
  add_quad(mesh, {2 - side / 2, 2 - side / 2, 1}, {side, 0, 0}, {0, side, 0}, "plate");
  return mesh;
}

// Standard deviation of the occlusion level when a region of `area` (out of
// `total`) is estimated with samples_per_unit_area and a fraction p of it is
// hidden: binomial, an upper bound for per-face stratified sampling.
double monte_carlo_sigma(double area, double total, double p, double samples_per_unit_area) {
  const double samples = area * samples_per_unit_area;
  return area * std::sqrt(p * (1 - p) / samples) / total;
}

TEST(MeshOcclusion, PlateShadowMatchesSimilarTriangles) {
  // One quad per room face, and a shadow of side 1.6 whose edges cut through
  // faces: a true Monte Carlo estimate.
  const double side = 0.8;
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 400;
  const auto result = compute_mesh_occlusion(room_with_plate(1, side), {kLamp}, options);
  const double total = total_area(side);
  const double expected = shadow_area(side) / total;
  const double tolerance =
      4 * monte_carlo_sigma(16, total, shadow_area(side) / 16, options.samples_per_unit_area);
  EXPECT_NEAR(result.occlusion_level, expected, tolerance);
  EXPECT_NEAR(result.total_area, total, 1e-9);
  EXPECT_NEAR(result.visible_area, total - shadow_area(side), tolerance * total);
  ASSERT_EQ(result.viewpoints.size(), 1u);
  EXPECT_NEAR(result.viewpoints[0].visible_fraction, 1 - expected, tolerance);
  // Groups: the plate is fully visible, the room carries the whole shadow.
  ASSERT_EQ(result.groups.size(), 2u);
  EXPECT_EQ(result.groups[1].name, "plate");
  EXPECT_DOUBLE_EQ(result.groups[1].occlusion_level, 0.0);
  EXPECT_NEAR(result.groups[0].occlusion_level, shadow_area(side) / kRoomArea,
              tolerance * total / kRoomArea);
}

TEST(MeshOcclusion, GridAlignedShadowIsExact) {
  // With 0.5 m cells and a shadow of [1,3]^2 every face is wholly lit or dark.
  const auto result = compute_mesh_occlusion(room_with_plate(8, 1.0), {kLamp}, {});
  EXPECT_NEAR(result.occlusion_level, shadow_area(1.0) / total_area(1.0), 1e-12);
}

// The floor grid has 0.5 m cells: the cells inside [1,3]^2 are entirely in the
// shadow and the ones outside entirely lit, whatever the samples.
void expect_faces_fully_in_or_out_of_shadow(double samples_per_unit_area) {
  const TriangleMesh mesh = room_with_plate();
  MeshOcclusionOptions options;
  options.samples_per_unit_area = samples_per_unit_area;
  const auto result = compute_mesh_occlusion(mesh, {kLamp}, options);
  std::size_t dark = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto v : mesh.faces[f]) centre += mesh.vertices[v] / 3.0;
    const bool on_floor = std::abs(centre.z()) < 1e-9;
    const bool under_plate =
        on_floor && centre.x() > 1 && centre.x() < 3 && centre.y() > 1 && centre.y() < 3;
    EXPECT_EQ(result.face_visible_fraction[f], under_plate ? 0.0f : 1.0f) << "face " << f;
    dark += under_plate ? 1 : 0;
  }
  EXPECT_EQ(dark, 32u);  // 16 cells of 0.5 m, two triangles each
}

TEST(MeshOcclusion, FacesFullyInOrOutOfShadowAreExact) {
  expect_faces_fully_in_or_out_of_shadow(50);
}

TEST(MeshOcclusion, SamplesTracedInMortonOrderGoBackToTheirFaces) {
  // 1,000 samples per m^2 of 81 m^2: two blocks of samples, each traced in
  // Morton order (mesh_sample_order), not face by face; every flag must still
  // land on its own sample.
  expect_faces_fully_in_or_out_of_shadow(1000);
}

TEST(MeshOcclusion, SampleOrderIsTheBlocksMortonOrder) {
  // The eight corners of a cube, shuffled, after two samples outside the
  // block: Morton order takes x fastest, then y, then z.
  MeshSamples samples;
  samples.points = {{9, 9, 9}, {9, 9, 9}, {0, 2, 2}, {2, 2, 0}, {0, 0, 0},
                    {2, 0, 2}, {0, 2, 0}, {2, 2, 2}, {2, 0, 0}, {0, 0, 2}};
  const std::vector<std::uint32_t> order = mesh_sample_order(samples, 2, 8);
  std::vector<Eigen::Vector3d> corners;
  for (const std::uint32_t k : order) corners.push_back(samples.points[2 + k] / 2.0);
  const std::vector<Eigen::Vector3d> expected = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                                 {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  EXPECT_EQ(corners, expected);
}

TEST(MeshOcclusion, MoreViewpointsNeverSeeLess) {
  const TriangleMesh mesh = room_with_plate();
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 100;
  const Eigen::Vector3d other(0.5, 0.5, 0.5);  // low, in a corner: sees under the plate
  const auto one = compute_mesh_occlusion(mesh, {kLamp}, options);
  const auto two = compute_mesh_occlusion(mesh, {kLamp, other}, options);
  EXPECT_LT(two.occlusion_level, one.occlusion_level);
  ASSERT_EQ(two.viewpoints.size(), 2u);
  // The union sees at least what each viewpoint sees alone (same seed, same samples).
  EXPECT_GE(1 - two.occlusion_level, two.viewpoints[0].visible_fraction - 1e-12);
  EXPECT_GE(1 - two.occlusion_level, two.viewpoints[1].visible_fraction - 1e-12);
  EXPECT_DOUBLE_EQ(two.viewpoints[0].visible_fraction, one.viewpoints[0].visible_fraction);
  EXPECT_EQ(two.rays, 2 * two.samples);
}

TEST(MeshOcclusion, ViewpointInsideAClosedBoxSeesOnlyItsInside) {
  TriangleMesh mesh;
  add_box(mesh, {0, 0, 0}, {4, 4, 3}, "room", 2);
  add_box(mesh, {1, 1, 0.5}, {2, 2, 1.5}, "crate", 2);  // closed, area 6
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 20;
  const auto result = compute_mesh_occlusion(mesh, {{1.5, 1.5, 1.0}}, options);
  const double total = 2 * 16 + 4 * 12 + 6;
  EXPECT_NEAR(result.occlusion_level, 1 - 6 / total, 1e-12);
  EXPECT_NEAR(result.visible_area, 6.0, 1e-12);
}

TEST(MeshOcclusion, DuplicateFacesDoNotHideEachOther) {
  // Two coincident faces: each sample lies on the other face, which must not
  // count as a blocker (it touches the shadow ray only at t = 0).
  TriangleMesh mesh;
  add_quad(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "a");
  add_quad(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "b");
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 200;
  const auto result = compute_mesh_occlusion(mesh, {{0.3, 0.4, 2.0}}, options);
  EXPECT_DOUBLE_EQ(result.occlusion_level, 0.0);
}

TEST(MeshOcclusion, SameSeedSameResultOtherSeedClose) {
  const TriangleMesh mesh = room_with_plate(1, 0.8);
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 30;
  options.seed = 5;
  const auto a = compute_mesh_occlusion(mesh, {kLamp}, options);
  options.threads = 1;
  const auto b = compute_mesh_occlusion(mesh, {kLamp}, options);
  EXPECT_EQ(a.occlusion_level, b.occlusion_level);  // also independent of threads
  EXPECT_EQ(a.face_visible_fraction, b.face_visible_fraction);
  options.seed = 6;
  const auto c = compute_mesh_occlusion(mesh, {kLamp}, options);
  EXPECT_NE(a.occlusion_level, c.occlusion_level);
  EXPECT_NEAR(a.occlusion_level, c.occlusion_level,
              8 * monte_carlo_sigma(16, total_area(0.8), 0.16, options.samples_per_unit_area));
}

TEST(MeshOcclusion, BruteForceModeGivesTheSameAnswer) {
  const TriangleMesh mesh = room_with_plate();
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 20;
  const auto fast = compute_mesh_occlusion(mesh, {kLamp, {3, 1, 2.5}}, options);
  options.octree.enable_acceleration = false;
  const auto slow = compute_mesh_occlusion(mesh, {kLamp, {3, 1, 2.5}}, options);
  EXPECT_EQ(fast.face_visible_fraction, slow.face_visible_fraction);
  EXPECT_EQ(slow.octree.leaves, 1u);
}

TEST(MeshOcclusion, RejectsBadInput) {
  const TriangleMesh mesh = room_with_plate();
  MeshOcclusionOptions options;
  EXPECT_THROW(compute_mesh_occlusion(TriangleMesh{}, {kLamp}, options), std::invalid_argument);
  EXPECT_THROW(compute_mesh_occlusion(mesh, {}, options), std::invalid_argument);
  EXPECT_THROW(compute_mesh_occlusion(mesh, {{NAN, 0, 0}}, options), std::invalid_argument);
  options.samples_per_unit_area = 0;
  EXPECT_THROW(compute_mesh_occlusion(mesh, {kLamp}, options), std::invalid_argument);
}

TEST(MeshOcclusion, CancelStopsWithCancelled) {
  std::atomic<bool> cancel{true};
  Progress progress;
  progress.cancel = &cancel;
  EXPECT_THROW(compute_mesh_occlusion(room_with_plate(), {kLamp}, {}, progress), Cancelled);
}

TEST(MeshOcclusion, ReportsProgressUpToOne) {
  double last = -1;
  bool traced = false;
  Progress progress;
  progress.report = [&](const std::string& stage, double fraction) {
    traced = traced || stage == "tracing";
    last = fraction;
  };
  compute_mesh_occlusion(room_with_plate(), {kLamp}, {}, progress);
  EXPECT_TRUE(traced);
  EXPECT_DOUBLE_EQ(last, 1.0);
}

}  // namespace
}  // namespace occlusion
