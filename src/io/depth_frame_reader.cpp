// A depth frame (descriptor + 16-bit depth PNG + optional colour PNG) as an
// organised cloud seen from its camera, the cloud's sensor and one station.

#include <string>

#include "cloud_formats.hpp"
#include "frame_descriptor.hpp"
#include "occlusion/io/input_error.hpp"
#include "png_image.hpp"

namespace occlusion::detail {

PointCloud read_depth_frame(const std::string& path, const CloudReadOptions& options,
                            CloudReadReport& /*report*/) {
  const FrameDescriptor frame = read_frame_descriptor(path);
  const DepthImage depth = read_depth_png(frame.depth_path);
  ColourImage colour;
  if (frame.colour_path) {
    colour = read_colour_png(*frame.colour_path);
    if (colour.width != depth.width || colour.height != depth.height) {
      throw InputError(path, 0,
                       "the colour image " + *frame.colour_path + " is " +
                           std::to_string(colour.width) + " x " + std::to_string(colour.height) +
                           " pixels, the depth image " + frame.depth_path + " " +
                           std::to_string(depth.width) + " x " + std::to_string(depth.height) +
                           ": a pixel's colour must be its depth's (register the colour to "
                           "the depth camera, or leave 'colour' out)");
    }
  }

  PointCloud cloud;
  ShiftedPositions shifted(options.shift);
  const Eigen::Matrix3d rotation = frame.rotation.toRotationMatrix();
  for (std::size_t v = 0; v < depth.height; ++v) {
    for (std::size_t u = 0; u < depth.width; ++u) {
      const std::size_t pixel = v * depth.width + u;
      const std::uint16_t value = depth.values[pixel];
      if (value == 0) continue;  // no measurement
      // Pinhole back-projection; pixel (u, v)'s centre is at (u, v), as the
      // datasets' intrinsics (TUM's cx = 319.5 for 640 columns) take it.
      const double z = value / frame.depth_scale;
      const Eigen::Vector3d camera((static_cast<double>(u) - frame.cx) * z / frame.fx,
                                   (static_cast<double>(v) - frame.cy) * z / frame.fy, z);
      const Eigen::Vector3d world = rotation * camera + frame.translation;
      const double xyz[3] = {world.x(), world.y(), world.z()};
      cloud.positions.push_back(shifted.local(xyz));
      cloud.pixels.push_back(static_cast<std::uint32_t>(pixel));
      if (frame.colour_path) {
        const std::uint8_t* rgb = colour.rgb.data() + 3 * pixel;
        cloud.colours.push_back({rgb[0], rgb[1], rgb[2]});
      }
    }
  }
  if (cloud.positions.empty()) {
    throw InputError(
        path, 0,
        "no points: every pixel of the depth image " + frame.depth_path + " is 0 (no measurement)");
  }
  cloud.shift = shifted.checked_shift(path);
  SensorFrame sensor;
  sensor.origin = cloud.to_local(frame.translation);
  sensor.orientation = frame.rotation;
  sensor.width = depth.width;
  sensor.height = depth.height;
  cloud.sensor = sensor;
  if (!sensor.organised()) cloud.pixels.clear();  // one row: no grid around a pixel
  cloud.stations.push_back({frame.name, sensor});
  cloud.station_ids.assign(cloud.size(), 0);
  return cloud;
}

}  // namespace occlusion::detail
