#pragma once
// The viewpoints each cloud job takes on a cloud when none is given (its
// request's defaults: the cloud's stations, else -poc's grid or -fscan's
// pattern on the robust frame), with the warnings the job gives about them.
// The server sends them with a loaded cloud, so that the viewer places the
// CLI's default viewpoints and shows its warnings: the defaults are stated
// once, in the requests (cloud_occlusion_job.hpp, scan_job.hpp).

#include <json/value.h>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

// {"cloud_occlusion": V, "scan": V, "robust_box": {"min", "max"}} with V =
// {"viewpoint_source", "viewpoints": [{"name", "position",
// "outside_occupied_space"}], "warnings": [...]}; positions in the file's
// frame (the cloud's global shift added back).
Json::Value default_viewpoints_json(const PointCloud& cloud);

}  // namespace occlusion
