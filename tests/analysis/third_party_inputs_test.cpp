// PCL, FLANN, OpenMP and qhull are only ever handed inputs they accept: a
// request with absurd threads or a cloud with stray points near ±3e38 ends in
// an exception the faces turn into an error, never in a dead process.

#include <gtest/gtest.h>

#include <stdexcept>

#include "occlusion/analysis/label_transfer.hpp"
#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "support/scenes.hpp"

namespace occlusion {
namespace {

PointCloud box_room_cloud(const Eigen::Vector3d& shift) {
  TriangleMesh room;
  testing::add_box(room, shift, shift + Eigen::Vector3d(4, 3.5, 2.5), "room");
  const MeshSamples samples = sample_mesh(room, 400.0, 3);
  PointCloud cloud;
  for (const auto& p : samples.points) cloud.positions.push_back(p.cast<float>());
  return cloud;
}

RegionGrowingOptions room_options() {
  RegionGrowingOptions options;
  options.max_cluster_size = 1000000;
  return options;
}

TEST(ThirdPartyInputs, FortyThousandThreadsEstimateTheSameMesh) {
  const PointCloud cloud = box_room_cloud(Eigen::Vector3d::Zero());
  RegionGrowingOptions options = room_options();
  options.threads = 1;
  const MeshEstimate one = estimate_mesh(cloud, options);
  options.threads = 40000;  // made OpenMP end the process
  const MeshEstimate many = estimate_mesh(cloud, options);
  EXPECT_EQ(one.mesh.vertices, many.mesh.vertices);
  EXPECT_EQ(one.mesh.faces, many.mesh.faces);
}

TEST(ThirdPartyInputs, PointsNearFloatMaxAreRefusedNotAborted) {
  for (const float far : {3e38f, -3e38f, 1e16f}) {
    PointCloud cloud = box_room_cloud(Eigen::Vector3d::Zero());
    cloud.positions.push_back(Eigen::Vector3f(far, 0.5f, -far));  // made FLANN abort
    try {
      estimate_mesh(cloud, room_options());
      ADD_FAILURE() << "a point at " << far << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("1e15"), std::string::npos) << e.what();
    }
  }
}

// The surface of the box [shift, shift + (4, 3.5, 2.5)] on a 1/16 grid: every
// coordinate is exact in float, near the origin and 4096 away alike.
PointCloud grid_room(const Eigen::Vector3f& shift) {
  const Eigen::Vector3f size(4, 3.5, 2.5);
  constexpr float kStep = 1.0f / 16;
  PointCloud cloud;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const float at : {0.0f, size[axis]}) {
      for (float a = 0; a <= size[u]; a += kStep) {
        for (float b = 0; b <= size[v]; b += kStep) {
          Eigen::Vector3f p;
          p[axis] = at;
          p[u] = a;
          p[v] = b;
          cloud.positions.push_back(p + shift);
        }
      }
    }
  }
  return cloud;
}

// Planes are estimated around the cloud's centre and moved back: a room
// shifted by an amount float holds exactly gives the same planes, shifted.
TEST(ThirdPartyInputs, ShiftedRoomGivesTheShiftedPlanes) {
  const Eigen::Vector3f shift(4096, -2048, 1024);
  const MeshEstimate here = estimate_mesh(grid_room(Eigen::Vector3f::Zero()), room_options());
  const MeshEstimate there = estimate_mesh(grid_room(shift), room_options());
  const Eigen::Vector3d offset = shift.cast<double>();
  ASSERT_EQ(here.planes.size(), 6u);
  ASSERT_EQ(there.planes.size(), here.planes.size());
  for (std::size_t p = 0; p < here.planes.size(); ++p) {
    const EstimatedPlane& a = here.planes[p];
    const EstimatedPlane& b = there.planes[p];
    EXPECT_LT((a.normal - b.normal).norm(), 1e-9) << p;
    EXPECT_NEAR(b.offset, a.offset - b.normal.dot(offset), 1e-6) << p;
    EXPECT_LT((b.centroid - (a.centroid + offset)).norm(), 1e-6) << p;
    EXPECT_NEAR(a.area, b.area, 1e-9) << p;
  }
  ASSERT_EQ(here.mesh.vertices.size(), there.mesh.vertices.size());
  for (std::size_t v = 0; v < here.mesh.vertices.size(); ++v) {
    EXPECT_LT((there.mesh.vertices[v] - (here.mesh.vertices[v] + offset)).norm(), 1e-6) << v;
  }
  EXPECT_EQ(here.point_cluster, there.point_cluster);
}

TEST(ThirdPartyInputs, LabelTransferRefusesFarSourcesAndLeavesFarTargetsUnmatched) {
  const std::vector<Eigen::Vector3f> source = {{0, 0, 0}, {1, 0, 0}};
  const std::vector<std::int32_t> labels = {3, 5};
  LabelTransferOptions options;
  options.max_distance = 0.1;
  const std::vector<Eigen::Vector3f> target = {{0.01f, 0, 0}, {3e38f, 0, 0}, {1, 0, -3e38f}};
  const LabelTransfer result = transfer_labels(source, labels, target, options);
  EXPECT_EQ(result.labels, (std::vector<std::int32_t>{3, -1, -1}));
  EXPECT_EQ(result.beyond_distance, 2u);

  const std::vector<Eigen::Vector3f> far_source = {{0, 0, 0}, {-3e38f, 0, 0}, {3e38f, 0, 0}};
  EXPECT_THROW(transfer_labels(far_source, {1, 2, 3}, target, options), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
