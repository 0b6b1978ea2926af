// The keys of -rgoc (config section occlusion.region_growing) and of
// extract_polygons (occlusion.extract_polygons): region growing, then, for
// -rgoc, the estimated mesh's occlusion as -moc measures it.

#include "occlusion/app/extract_polygons_job.hpp"
#include "occlusion/app/region_growing_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

namespace {
const char kCloudDoc[] =
    "point cloud: a file in any format of docs/formats.md (.pcd, .ply, .e57, .las, ...), or an "
    "S3DIS room/Area or ScanNet scene folder";
}

const Keys<RegionGrowingRequest>& region_growing_keys() {
  using R = RegionGrowingRequest;
  static const Keys<R> keys = join<R>({
      {input_key(&R::path, kCloudDoc)},
      viewpoint_keys(&R::viewpoints),
      mount(estimation_keys(), &R::estimation),
      {samples_per_unit_area_key(&R::samples_per_unit_area),
       key("min_samples", &R::min_samples)
           .range(0, 1e12)
           .metavar("N")
           .doc("the sampling density is raised until the mesh gets at least N samples (0: "
                "never); the JSON's mesh.sampling reports the budget"),
       octree_resolution_key(&R::octree_resolution),
       enable_acceleration_key(&R::enable_acceleration), seed_key(&R::seed),
       threads_key(&R::threads), skip_bad_lines_key(&R::skip_bad_lines),
       max_memory_key(&R::max_memory_mb), max_work_key(&R::max_work),
       out_key(&R::out,
               "write CLOUD.rgoc.obj and CLOUD.rgoc.ply (the estimated mesh, group = cluster; "
               "the PLY with per-face visible_fraction), CLOUD.segmented.ply (every point with "
               "its cluster, -1 for none) and CLOUD.rgoc.json")},
  });
  return keys;
}

const Keys<ExtractPolygonsRequest>& extract_polygons_keys() {
  using R = ExtractPolygonsRequest;
  static const Keys<R> keys = join<R>({
      {input_key(&R::path, kCloudDoc)},
      mount(estimation_keys(), &R::estimation),
      {threads_key(&R::threads), skip_bad_lines_key(&R::skip_bad_lines),
       max_memory_key(&R::max_memory_mb),
       out_key(&R::out,
               "write CLOUD.polygons.obj, CLOUD.segmented.ply (an int cluster per point) and "
               "CLOUD.polygons.json")},
  });
  return keys;
}

}  // namespace occlusion
