// The keys of -fscan (config section occlusion.scan).

#include "occlusion/app/scan_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

const Keys<ScanRequest>& scan_keys() {
  using R = ScanRequest;
  static const Keys<R> keys = join<R>({
      {input_key(&R::path,
                 "point cloud: a file in any format of docs/formats.md (.pcd, .ply, .e57, .las, "
                 "...), or an S3DIS room/Area or ScanNet scene folder")},
      viewpoint_keys(&R::viewpoints),
      {primitive_key(&R::primitive), point_radius_key(&R::point_radius),
       disc_coverage_key(&R::disc_coverage), normal_neighbours_key(&R::normal_neighbours),
       self_tolerance_key(&R::self_tolerance), frame_key(&R::frame), up_key(&R::up),
       octree_resolution_key(&R::octree_resolution),
       enable_acceleration_key(&R::enable_acceleration),
       cloud_format_key(&R::format, "format of the written clouds"),
       skip_bad_lines_key(&R::skip_bad_lines), scans_key(&R::scans), min_range_key(&R::min_range),
       max_range_key(&R::max_range), class_names_key(&R::class_names_path),
       threads_key(&R::threads), max_memory_key(&R::max_memory_mb), max_work_key(&R::max_work),
       out_key(&R::out,
               "write CLOUD.scan.FMT (the seen points, all attributes), CLOUD.scan_full.FMT "
               "(every point + visible_count and first_station: the first viewpoint that sees it, "
               "from 1, -1 for none) and CLOUD.fscan.json")},
  });
  return keys;
}

}  // namespace occlusion
