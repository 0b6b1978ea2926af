#include "occlusion/analysis/inside_solid.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "occlusion/analysis/mesh_occlusion.hpp"
#include "support/scenes.hpp"

namespace occlusion {
namespace {

using testing::add_quad;

// The box [lo, hi] with every face's normal (e1 x e2) pointing out of it, or
// into it when `inward` (a room seen from inside).
void add_oriented_box(TriangleMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                      bool inward) {
  const Eigen::Vector3d size = hi - lo;
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3d ea = Eigen::Vector3d::Zero(), eb = Eigen::Vector3d::Zero();
    ea[(axis + 1) % 3] = size[(axis + 1) % 3];
    eb[(axis + 2) % 3] = size[(axis + 2) % 3];  // ea x eb points along +axis
    for (const bool high : {false, true}) {
      Eigen::Vector3d corner = lo;
      corner[axis] = high ? hi[axis] : lo[axis];
      const bool along_plus = high != inward;
      if (along_plus) {
        add_quad(mesh, corner, ea, eb, "box");
      } else {
        add_quad(mesh, corner, eb, ea, "box");
      }
    }
  }
}

TEST(InsideSolid, ViewpointInsideAClosedSolidSeesOnlyBackFaces) {
  TriangleMesh mesh;
  add_oriented_box(mesh, Eigen::Vector3d::Zero(), Eigen::Vector3d(6, 5, 3), true);  // the room
  // A cupboard off the floor (a face on the floor would tie with it).
  add_oriented_box(mesh, Eigen::Vector3d(1, 1, 0.5), Eigen::Vector3d(2, 2, 1.5), false);
  const std::vector<double> shares =
      back_face_shares(mesh, {Eigen::Vector3d(4, 3, 1.5), Eigen::Vector3d(1.5, 1.5, 1.0)});
  ASSERT_EQ(shares.size(), 2u);
  EXPECT_EQ(shares[0], 0.0);  // in the room: every first hit is a front face
  EXPECT_EQ(shares[1], 1.0);  // in the cupboard: every ray hits its inside
}

// -moc warns from these shares without a tree of its own: compute_mesh_occlusion
// measures them with its tree, in its frame around the mesh's centre.
TEST(InsideSolid, MeshOcclusionMeasuresTheSharesWithItsOwnTree) {
  TriangleMesh mesh;
  add_oriented_box(mesh, Eigen::Vector3d::Zero(), Eigen::Vector3d(6, 5, 3), true);
  add_oriented_box(mesh, Eigen::Vector3d(1, 1, 0.5), Eigen::Vector3d(2, 2, 1.5), false);
  const std::vector<Eigen::Vector3d> viewpoints = {Eigen::Vector3d(4, 3, 1.5),
                                                   Eigen::Vector3d(1.5, 1.5, 1.0)};
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 1.0;
  const MeshOcclusionResult result = compute_mesh_occlusion(mesh, viewpoints, options);
  ASSERT_EQ(result.viewpoints.size(), 2u);
  EXPECT_EQ(result.viewpoints[0].back_face_share, 0.0);
  EXPECT_EQ(result.viewpoints[1].back_face_share, 1.0);
}

TEST(InsideSolid, RoomWhoseFacesPointOutLooksTheSame) {
  TriangleMesh mesh;
  add_oriented_box(mesh, Eigen::Vector3d::Zero(), Eigen::Vector3d(6, 5, 3), false);
  EXPECT_EQ(back_face_shares(mesh, {Eigen::Vector3d(3, 2, 1)})[0], 1.0);
  EXPECT_THROW(back_face_shares(TriangleMesh{}, {Eigen::Vector3d::Zero()}), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
