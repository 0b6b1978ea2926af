#pragma once
// The keys of the virtual scanner's two sensor models, declared once for
// their structs (analysis/sensor_model.hpp) and mounted into each request
// that holds one.

#include "occlusion/analysis/sensor_model.hpp"
#include "occlusion/app/key.hpp"

namespace occlusion {

const Keys<LaserScannerModel>& laser_scanner_keys();
const Keys<DepthCameraModel>& depth_camera_keys();

// The virtual scanner's incidence limit (SimulationOptions::max_incidence_deg).
template <class R>
KeyBuilder<R> max_incidence_key(double R::*field) {
  return key("max_incidence", field)
      .positive_up_to(90)
      .unit("degrees")
      .doc(
          "returns whose beam meets the surface farther than this from its normal are lost "
          "(too little light comes back)");
}

}  // namespace occlusion
