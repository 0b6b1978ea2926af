// The keys of register (config section occlusion.register).

#include "occlusion/app/register_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

const Keys<RegisterRequest>& register_keys() {
  using R = RegisterRequest;
  static const Keys<R> keys = {
      input_key(&R::path,
                "the source scan, in its scanner's frame: its pose onto the target is refined; or "
                "a project file (NAME.project.json): each scan after the first is registered "
                "onto the first from its pose, and OUT/NAME.refined.project.json written"),
      key("target", &R::target)
          .path()
          .metavar("CLOUD")
          .doc("the scan the source is registered onto (its frame is the pose's target frame)"),
      key("initial_pose", &R::initial_pose)
          .path()
          .metavar("FILE")
          .doc("pose file taking the source's points into the target's frame, within about the "
               "coarsest search distance and max_rotation of the truth; the refined pose is "
               "written in its format"),
      key("pose_format", &R::pose_format)
          .choices({"auto", "matrix", "tum", "3dtk"})
          .doc("the initial pose file's format (docs/formats.md, Poses); auto: a .pose file is "
               "3DTK's, 16 numbers a matrix, a line of 8 a TUM trajectory line"),
      key("method", &R::method)
          .choices({"gicp", "icp_plane", "ndt"})
          .doc("gicp: Generalized ICP (plane to plane; the default, robust on laser rooms and "
               "simulated scans); icp_plane: point-to-plane ICP; ndt: PCL's Normal "
               "Distributions Transform, as its tutorial"),
      key("levels", &R::levels)
          .range(1, 8)
          .metavar("N")
          .doc("voxel pyramid levels, coarsest first, each voxel 3 x the next finer"),
      key("finest_voxel", &R::finest_voxel)
          .positive_up_to(1e6)
          .unit("scene units")
          .metavar("V")
          .doc("voxel of the finest level; auto: 2 x the larger point spacing of the two scans"),
      key("max_distance", &R::max_distance)
          .positive_up_to(1e6)
          .unit("scene units")
          .metavar("D")
          .doc("the coarsest level's search distance (finer levels' shrink with their voxels), "
               "how far off the initial pose may be; auto: 3 x the coarsest voxel"),
      key("max_iterations", &R::max_iterations)
          .range(1, 10000)
          .metavar("N")
          .doc("iterations per level; the finest level must converge within them"),
      key("min_overlap", &R::min_overlap)
          .positive_up_to(1)
          .metavar("F")
          .doc("share of the source's points that must have a target point within the finest "
               "search distance after registration, else the pair is refused"),
      key("max_rotation", &R::max_rotation)
          .positive_up_to(180)
          .unit("degrees")
          .doc("a refined pose turned farther than this from the initial one is refused (a "
               "different fit, not a refinement)"),
      skip_bad_lines_key(&R::skip_bad_lines),
      threads_key(&R::threads),
      out_key(&R::out,
              "write SOURCE.refined.EXT (the refined pose, in the initial pose's format and "
              "extension) and SOURCE.register.json"),
  };
  return keys;
}

}  // namespace occlusion
