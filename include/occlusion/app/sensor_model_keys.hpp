#pragma once
// The keys of the virtual scanner's two sensor models, declared once for
// their structs (analysis/sensor_model.hpp) and mounted into each request
// that holds one.

#include "occlusion/analysis/sensor_model.hpp"
#include "occlusion/app/key.hpp"

namespace occlusion {

const Keys<LaserScannerModel>& laser_scanner_keys();
const Keys<DepthCameraModel>& depth_camera_keys();

}  // namespace occlusion
