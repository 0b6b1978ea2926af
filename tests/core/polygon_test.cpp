#include "occlusion/core/polygon.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "occlusion/core/random.hpp"

namespace occlusion {
namespace {

constexpr double kPi = 3.14159265358979323846;

// An L in plane coordinates (a, b): [0,2]x[0,1] and [0,1]x[0,2], the notch
// (1,2]x(1,2] cut out of its bounding box. Counter-clockwise.
const std::vector<Eigen::Vector2d> kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

bool in_closed_l(double a, double b) {
  return (a >= 0 && a <= 2 && b >= 0 && b <= 1) || (a >= 0 && a <= 1 && b >= 0 && b <= 2);
}

// The L embedded in 3-D as origin + a * axis_a + b * axis_b.
struct Embedding {
  Eigen::Vector3d origin, axis_a, axis_b;
  Eigen::Vector3d at(double a, double b) const { return origin + a * axis_a + b * axis_b; }
  std::vector<Eigen::Vector3d> embed(const std::vector<Eigen::Vector2d>& shape) const {
    std::vector<Eigen::Vector3d> points;
    for (const Eigen::Vector2d& p : shape) points.push_back(at(p.x(), p.y()));
    return points;
  }
};

// The wall y = 3, with a along x and b along z: rays along y have exact t.
const Embedding kWall{{0, 3, 0}, {1, 0, 0}, {0, 0, 1}};
// A tilted plane far from the world origin.
const Embedding kTilted{{250, -40, 7}, {0.6, 0.8, 0}, {-0.48, 0.36, 0.8}};

Ray ray_from(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  return Ray{origin.cast<float>(), direction.cast<float>()};
}

TEST(PlanarPolygon, FitsThePlaneOfNoisyPoints) {
  const Eigen::Vector3d normal = Eigen::Vector3d(1, 2, 3).normalized();
  const Eigen::Vector3d u = normal.cross(Eigen::Vector3d::UnitX()).normalized();
  const Eigen::Vector3d v = normal.cross(u);
  const Eigen::Vector3d centre(4, -1, 2);
  Rng rng(3);
  std::vector<Eigen::Vector3d> ring;
  for (int i = 0; i < 64; ++i) {
    const double angle = 2.0 * kPi * i / 64.0;
    const double noise = 2e-3 * (rng.uniform() - 0.5);
    ring.push_back(centre + 2.0 * (std::cos(angle) * u + std::sin(angle) * v) + noise * normal);
  }
  const PlanarPolygon polygon(ring);
  // Noise of 1e-3 across a radius of 2 tilts the fit by well under 1e-3 rad.
  EXPECT_GT(std::abs(polygon.normal().dot(normal)), std::cos(1e-3));
  EXPECT_NEAR(polygon.normal().norm(), 1.0, 1e-12);
  EXPECT_LT((polygon.origin() - centre).norm(), 1e-3);
  // The basis is orthonormal and right-handed, and the projection is in the plane.
  EXPECT_NEAR(polygon.axis_u().dot(polygon.axis_v()), 0.0, 1e-12);
  EXPECT_NEAR(polygon.axis_u().dot(polygon.normal()), 0.0, 1e-12);
  EXPECT_LT((polygon.axis_u().cross(polygon.axis_v()) - polygon.normal()).norm(), 1e-12);
  for (const Eigen::Vector3d& p : polygon.vertices()) {
    EXPECT_NEAR((p - polygon.origin()).dot(polygon.normal()), 0.0, 1e-12);
  }
  // A regular 64-gon of circumradius 2.
  EXPECT_NEAR(polygon.area(), 0.5 * 64 * 4 * std::sin(2 * kPi / 64), 1e-4);
}

TEST(PlanarPolygon, NormalFollowsTheWinding) {
  const std::vector<Eigen::Vector3d> ccw = {{0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};
  const std::vector<Eigen::Vector3d> cw(ccw.rbegin(), ccw.rend());
  const PlanarPolygon up(ccw), down(cw);
  EXPECT_LT((up.normal() - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  EXPECT_LT((down.normal() + Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(up.area(), 4.0);
  EXPECT_DOUBLE_EQ(down.area(), 4.0);
}

TEST(PlanarPolygon, SquareContains) {
  const PlanarPolygon square({{0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}});
  const auto contains = [&](double x, double y) {
    return square.contains(square.to_plane({x, y, 1}));
  };
  EXPECT_TRUE(contains(1, 1));
  EXPECT_TRUE(contains(0.01, 1.99));
  EXPECT_FALSE(contains(-0.01, 1));
  EXPECT_FALSE(contains(3, 1));
  EXPECT_FALSE(contains(2.01, 2.01));
  for (const Eigen::Vector3d& corner : square.vertices()) {
    EXPECT_TRUE(square.contains(square.to_plane(corner)));
  }
  EXPECT_TRUE(contains(1, 0));  // edge midpoints
  EXPECT_TRUE(contains(2, 1));
  EXPECT_TRUE(contains(0, 0.5));
  // A point above the plane is judged by its projection.
  EXPECT_TRUE(square.contains(square.to_plane({1, 1, 7})));
}

// Every point of a grid that straddles the L, edges and vertices included,
// against the L's closed definition. Off-boundary grid points are at least a
// grid step from it, so the answer is exact.
void expect_l_contains_exactly(const Embedding& embedding) {
  const PlanarPolygon l(embedding.embed(kL));
  EXPECT_NEAR(l.area(), 3.0, 1e-12);
  int inside = 0, outside = 0;
  for (int i = -4; i <= 20; ++i) {
    for (int j = -4; j <= 20; ++j) {
      const double a = 0.125 * i, b = 0.125 * j;
      const bool expected = in_closed_l(a, b);
      EXPECT_EQ(l.contains(l.to_plane(embedding.at(a, b))), expected) << a << ", " << b;
      (expected ? inside : outside)++;
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

TEST(PlanarPolygon, LShapeContainsExactlyOnAWall) {
  expect_l_contains_exactly(kWall);
}

TEST(PlanarPolygon, LShapeContainsExactlyOnATiltedPlane) {
  expect_l_contains_exactly(kTilted);
}

TEST(PlanarPolygon, LShapeNamedCases) {
  const PlanarPolygon l(kWall.embed(kL));
  const auto contains = [&](double a, double b) { return l.contains(l.to_plane(kWall.at(a, b))); };
  EXPECT_TRUE(contains(0.5, 0.5));   // the corner square
  EXPECT_TRUE(contains(1.5, 0.5));   // the foot
  EXPECT_TRUE(contains(0.5, 1.5));   // the upright
  EXPECT_FALSE(contains(1.5, 1.5));  // the notch: in the bounding box, not in the L
  EXPECT_FALSE(contains(1.01, 1.01));
  EXPECT_TRUE(contains(1, 1));    // the reflex vertex
  EXPECT_TRUE(contains(1.5, 1));  // the notch's edges
  EXPECT_TRUE(contains(1, 1.5));
  EXPECT_TRUE(contains(2, 0));  // a convex vertex
  EXPECT_FALSE(contains(2.5, 0.5));
  EXPECT_FALSE(contains(-0.5, 1));
}

TEST(PlanarPolygon, RayThroughTheLHitsAtExactT) {
  const PlanarPolygon l(kWall.embed(kL));
  const auto t = l.intersect(ray_from({0.5, 0, 0.5}, {0, 1, 0}));
  ASSERT_TRUE(t);
  EXPECT_DOUBLE_EQ(*t, 3.0);
  // Unnormalised direction: t in its units. From the other side: both faces.
  EXPECT_DOUBLE_EQ(l.intersect(ray_from({1.5, 0, 0.5}, {0, 2, 0})).value_or(-1), 1.5);
  EXPECT_DOUBLE_EQ(l.intersect(ray_from({0.5, 7, 1.5}, {0, -1, 0})).value_or(-1), 4.0);
  // Oblique, through (0.5, 3, 1.5) at t = 1.
  EXPECT_NEAR(l.intersect(ray_from({1.5, 2, 0.5}, {-1, 1, 1})).value_or(-1), 1.0, 1e-6);
  // Through the reflex vertex and an edge: the boundary belongs to the L.
  EXPECT_TRUE(l.intersect(ray_from({1, 0, 1}, {0, 1, 0})));
  EXPECT_TRUE(l.intersect(ray_from({2, 0, 0.5}, {0, 1, 0})));
}

TEST(PlanarPolygon, RayThroughTheNotchMisses) {
  const PlanarPolygon l(kWall.embed(kL));
  EXPECT_FALSE(l.intersect(ray_from({1.5, 0, 1.5}, {0, 1, 0})));
  EXPECT_FALSE(l.intersect(ray_from({1.9, 0, 1.1}, {0, 1, 0})));
  EXPECT_FALSE(l.intersect(ray_from({3, 0, 0.5}, {0, 1, 0})));  // beside it
}

TEST(PlanarPolygon, ParallelAndBehindMiss) {
  const PlanarPolygon l(kWall.embed(kL));
  EXPECT_FALSE(l.intersect(ray_from({-1, 3, 0.5}, {1, 0, 0})));   // in the plane, across the L
  EXPECT_FALSE(l.intersect(ray_from({-1, 2, 0.5}, {1, 0, 1})));   // beside the plane
  EXPECT_FALSE(l.intersect(ray_from({0.5, 5, 0.5}, {0, 1, 0})));  // the L is behind
}

TEST(PlanarPolygon, IntervalIsClosed) {
  const PlanarPolygon l(kWall.embed(kL));
  Ray ray = ray_from({0.5, 0, 0.5}, {0, 1, 0});  // crosses at t = 3
  ray.t_max = 3.0f;
  EXPECT_TRUE(l.intersect(ray));
  ray.t_max = std::nextafter(3.0f, 0.0f);
  EXPECT_FALSE(l.intersect(ray));
  ray.t_max = 10.0f;
  ray.t_min = 3.0f;
  EXPECT_TRUE(l.intersect(ray));
  ray.t_min = std::nextafter(3.0f, 4.0f);
  EXPECT_FALSE(l.intersect(ray));
}

TEST(PlanarPolygon, RejectsBadInput) {
  using Points = std::vector<Eigen::Vector3d>;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(PlanarPolygon(Points{}), std::invalid_argument);
  EXPECT_THROW(PlanarPolygon(Points{{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(PlanarPolygon(Points{{0, 0, 0}, {1, 0, 0}, {nan, 1, 0}}), std::invalid_argument);
  EXPECT_THROW(PlanarPolygon(Points{{0, 0, 0}, {1, 0, 0}, {0, inf, 0}}), std::invalid_argument);
  // Collinear, coincident, collinear within rounding, and collinear far from the origin.
  EXPECT_THROW(PlanarPolygon(Points{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}}),
               std::invalid_argument);
  EXPECT_THROW(PlanarPolygon(Points(4, Eigen::Vector3d(5, 5, 5))), std::invalid_argument);
  EXPECT_THROW(PlanarPolygon(Points{{0, 0, 0}, {1, 1e-9, 0}, {2, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(
      PlanarPolygon(Points{{1e6, 1e6, 0}, {1e6 + 0.1, 1e6 + 0.2, 0}, {1e6 + 0.3, 1e6 + 0.6, 0}}),
      std::invalid_argument);
  // A thin but real opening is kept.
  EXPECT_NO_THROW(PlanarPolygon(Points{{0, 0, 0}, {1, 0, 0}, {1, 1e-3, 0}, {0, 1e-3, 0}}));
}

}  // namespace
}  // namespace occlusion
