// The keys of -moc (config section occlusion.mesh).

#include "occlusion/app/mesh_occlusion_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

const Keys<MeshOcclusionRequest>& mesh_occlusion_keys() {
  using R = MeshOcclusionRequest;
  static const Keys<R> keys = join<R>({
      {input_key(&R::path, "triangle mesh: Wavefront OBJ or PLY (io/mesh_reader.hpp)")},
      viewpoint_keys(&R::viewpoints),
      {samples_per_unit_area_key(&R::samples_per_unit_area),
       octree_resolution_key(&R::octree_resolution),
       enable_acceleration_key(&R::enable_acceleration), seed_key(&R::seed),
       threads_key(&R::threads), max_memory_key(&R::max_memory_mb), max_work_key(&R::max_work),
       out_key(&R::out,
               "write MESH.moc.json, .ply (per-face visible_fraction, colour ramp, group_id) "
               "and .csv")},
  });
  return keys;
}

}  // namespace occlusion
