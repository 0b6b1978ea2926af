#pragma once
// Work whose size would exceed a memory budget is refused before it starts,
// with the estimate and what it is made of, instead of being attempted until
// the machine (or the server every client shares) runs out of memory. Each
// job's estimate is here, once: it counts the large arrays the job allocates
// for its request and input, not every byte.

#include <cstdint>
#include <string>

#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/core/mesh.hpp"

namespace occlusion {

struct MemoryEstimate {
  std::uint64_t bytes = 0;  // saturated: an absurd request never wraps to a small one
  std::string made_of;      // for people: "2,000,000 samples x 7 viewpoints"
  std::string lower;        // the keys that size it, when one or two do: "samples_per_unit_area"
};

// The machine's physical memory in MiB; 0 when the system does not say.
std::uint64_t machine_memory_mb();

// UsageError, naming the estimate, what to lower and `max_memory_mb`, when the
// estimate exceeds max_memory_mb; with no budget (0), when it exceeds the
// machine's memory.
void check_memory_budget(const MemoryEstimate& estimate, std::uint64_t max_memory_mb);

// -moc: samples (exactly as sample_mesh counts them) x viewpoints, the octree.
// -rgoc passes the density its min_samples raised it to.
MemoryEstimate mesh_occlusion_memory(const TriangleMesh& mesh, double samples_per_unit_area,
                                     std::size_t viewpoints);
// -poc: the point octree, and each viewpoint's escape directions when kept.
// `discs`: the points are traced as discs (app/point_model.hpp), whose model
// and its estimation take more per point than spheres.
MemoryEstimate cloud_occlusion_memory(std::size_t points, std::size_t viewpoints,
                                      std::uint64_t rays_per_viewpoint, bool keep_escapes,
                                      bool discs);
// -fscan: the point octree and the per-point counts.
MemoryEstimate scan_memory(std::size_t points, std::size_t viewpoints, bool discs);
// simulate: a point per beam at most, with its truth, and the mesh's octree.
MemoryEstimate simulate_memory(const TriangleMesh& mesh, std::uint64_t beams_per_station,
                               std::size_t stations, bool truth);
// plan: the scene's model (scan_memory or mesh_occlusion_memory with one
// viewpoint), what plan keeps per target, the coverage matrix of `candidates`
// rows over `targets` and, with `intervisible`, the pairs of candidates.
// Known before any sample is drawn or point model made (total_samples counts
// a mesh's targets).
MemoryEstimate plan_memory(MemoryEstimate model, std::uint64_t targets, std::size_t candidates,
                           bool intervisible);
// -rgoc and extract_polygons: PCL's cloud, normals, kd-tree and the
// neighbour lists of region growing and normal estimation.
MemoryEstimate region_growing_memory(std::size_t points, const RegionGrowingOptions& options);

}  // namespace occlusion
