#include "occlusion/analysis/inside_solid.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis_support.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

std::vector<double> back_face_shares(const TriangleMesh& mesh,
                                     const std::vector<Eigen::Vector3d>& viewpoints) {
  analysis_support::check_viewpoints(viewpoints, "inside solid");
  if (mesh.face_count() == 0) throw std::invalid_argument("inside solid: the mesh has no faces");
  return back_face_shares(TriangleOctree(pack_triangles(mesh.triangles())), viewpoints);
}

std::vector<double> back_face_shares(const TriangleOctree& tree,
                                     const std::vector<Eigen::Vector3d>& viewpoints) {
  analysis_support::check_viewpoints(viewpoints, "inside solid");
  // An unrotated Fibonacci lattice: fixed, evenly spread directions.
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  std::vector<double> shares;
  for (const auto& viewpoint : viewpoints) {
    std::size_t back = 0;
    for (std::size_t k = 0; k < kInsideProbeRays; ++k) {
      const double z = 1.0 - (2.0 * static_cast<double>(k) + 1.0) / kInsideProbeRays;
      const double r = std::sqrt(1.0 - z * z);
      const double phi = golden * static_cast<double>(k);
      const Eigen::Vector3f direction(static_cast<float>(r * std::cos(phi)),
                                      static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
      Ray ray;
      ray.origin = viewpoint.cast<float>();
      ray.direction = direction;
      ray.t_min = 0.0f;
      ray.t_max = std::numeric_limits<float>::infinity();
      const auto hit = tree.intersect(ray);
      if (hit && direction.dot(tree.shape(hit->primitive_id).normal) > 0.0f) ++back;
    }
    shares.push_back(static_cast<double>(back) / static_cast<double>(kInsideProbeRays));
  }
  return shares;
}

}  // namespace occlusion
