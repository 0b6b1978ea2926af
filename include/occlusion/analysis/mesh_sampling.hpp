#pragma once
// Area-proportional sampling of a triangle mesh.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "occlusion/core/mesh.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

// Samples of all faces, stored face by face: the samples of face f are
// points[first[f] .. first[f + 1]).
struct MeshSamples {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> face;  // face of each sample
  std::vector<std::size_t> first;   // size face_count + 1

  std::size_t size() const { return points.size(); }
  std::size_t count_on(std::size_t f) const { return first[f + 1] - first[f]; }
};

// Face f gets max(1, round(area_f * samples_per_unit_area)) samples, so no face
// silently drops out; each sample uses the seed's barycentric formula with a
// random stream derived from (seed, f), so the result does not depend on the
// order or thread in which faces are processed.
// Throws std::invalid_argument if samples_per_unit_area is not finite and > 0,
// or gives more samples than a vector can hold (callers check the memory
// the samples need first: app/memory_budget).
// Reports stage "sampling" and checks `progress`'s cancel flag every block of
// samples (a dense mesh takes tens of seconds).
MeshSamples sample_mesh(const TriangleMesh& mesh, double samples_per_unit_area, std::uint64_t seed,
                        const Progress& progress = {});

// Number of samples face f of the given area gets (the rule above); the
// largest size_t where the count does not fit in one.
std::size_t samples_for_area(double area, double samples_per_unit_area);

// How many samples sample_mesh would draw at this density (saturating, as above).
std::size_t total_samples(const TriangleMesh& mesh, double samples_per_unit_area);

// A density fitted to the mesh's scale: samples_per_unit_area when it already
// gives at least `min_samples` samples, else the smallest density (to 1e-9
// relative) that does. A density per unit area means nothing across scales: a
// 30 cm object at 100 per square metre would get one sample per face and a
// level that is pure rounding. Same std::invalid_argument as sample_mesh.
double density_for_min_samples(const TriangleMesh& mesh, double samples_per_unit_area,
                               std::size_t min_samples);

}  // namespace occlusion
