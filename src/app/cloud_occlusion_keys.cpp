// The keys of -poc (config section occlusion.point_cloud); its tracing keys
// also serve the study.

#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

const Keys<CloudOcclusionRequest>& cloud_tracing_keys() {
  using R = CloudOcclusionRequest;
  static const Keys<R> keys = {
      key("num_rays_per_vp", &R::num_rays_per_vp)
          .range(1, 100'000'000)
          .metavar("N")
          .doc("rays from each viewpoint's light source"),
      primitive_key(&R::primitive),
      point_radius_key(&R::point_radius),
      disc_coverage_key(&R::disc_coverage),
      normal_neighbours_key(&R::normal_neighbours),
      key("polygon_path", &R::polygon_path)
          .path()
          .metavar("FILE")
          .doc("openings (windows, doors): a ray leaving through one is no occlusion ray; "
               "docs/formats.md"),
      octree_resolution_key(&R::octree_resolution),
      enable_acceleration_key(&R::enable_acceleration),
      key("sampling", &R::sampling)
          .choices({"uniform", "fibonacci"})
          .doc("ray directions: the seed's random theta/phi, or a randomly rotated Fibonacci "
               "lattice (lower variance)"),
      key("light_radius", &R::light_radius)
          .range(0, 1e6)
          .unit("scene units")
          .metavar("R")
          .doc("radius of the spherical light source"),
      key("exterior", &R::exterior)
          .doc("also the exterior-structure variant: only exterior_classes block rays; adds the "
               "interior/exterior point ratio"),
      key("exterior_classes", &R::exterior_classes)
          .metavar("A,B,...")
          .implies("exterior", true)
          .doc("classes of the exterior structure"),
      skip_bad_lines_key(&R::skip_bad_lines),
      scans_key(&R::scans),
      min_range_key(&R::min_range),
      max_range_key(&R::max_range),
      class_names_key(&R::class_names_path),
      seed_key(&R::seed),
      threads_key(&R::threads),
  };
  return keys;
}

const Keys<CloudOcclusionRequest>& cloud_occlusion_keys() {
  using R = CloudOcclusionRequest;
  static const Keys<R> keys = join<R>({
      {input_key(&R::path,
                 "point cloud: a file in any format of docs/formats.md (.pcd, .ply, .e57, .las, "
                 "...), or an S3DIS room/Area or ScanNet scene folder")},
      viewpoint_keys(&R::viewpoints),
      cloud_tracing_keys(),
      {frame_key(&R::frame), up_key(&R::up),
       key("field_of_view", &R::field_of_view)
           .range(0.5, 179.5)
           .max_items(2)
           .unit("degrees")
           .metavar("H,V")
           .doc("treat the cloud as one depth frame with this field of view around the sensor's "
                "+z: rays outside it are counted apart (outside_view_rays); empty: measured "
                "from an organised or VIEWPOINT PCD"),
       max_memory_key(&R::max_memory_mb), max_work_key(&R::max_work),
       key("escape_directions", &R::escape_directions)
           .doc("keep each occlusion ray's direction in the report (always kept with out)"),
       out_key(&R::out,
               "write CLOUD.poc.json and CLOUD.poc.escapes.csv (directions of the occlusion "
               "rays, per viewpoint)")},
  });
  return keys;
}

}  // namespace occlusion
