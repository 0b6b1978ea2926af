// A depth frame (descriptor + 16-bit depth PNG + optional colour PNG) as an
// organised cloud seen from its camera, the cloud's sensor and one station.

#include <algorithm>
#include <cstdint>
#include <string>

#include "cloud_formats.hpp"
#include "frame_descriptor.hpp"
#include "number_text.hpp"
#include "occlusion/io/input_error.hpp"
#include "png_image.hpp"

namespace occlusion::detail {

namespace {

// The bytes a frame of `pixels` takes as it is read, at most one point a
// pixel: the decoded depth (2), and each point's position (12), pixel (4) and
// station (4); with colour, the decoded image and the points' colours (3 + 3).
std::uint64_t frame_bytes(std::uint64_t pixels, bool colour) {
  return pixels * (2 + 12 + 4 + 4 + (colour ? 3 + 3 : 0));
}

}  // namespace

PointCloud read_depth_frame(const std::string& path, const CloudReadOptions& options,
                            CloudReadReport& report) {
  const FrameDescriptor frame = read_frame_descriptor(path);
  const auto within_budget = [&](std::size_t width, std::size_t height) {
    const std::uint64_t pixels = std::uint64_t{width} * height;
    const std::uint64_t bytes = frame_bytes(pixels, frame.colour_path.has_value());
    const std::uint64_t budget = options.max_memory_mb;
    if (budget == 0 || budget > (bytes >> 20) || bytes <= (budget << 20)) return;
    throw InputError(
        path, 0,
        "the depth image " + frame.depth_path + " is " + std::to_string(width) + " x " +
            std::to_string(height) + " pixels: read, its up to " + std::to_string(pixels) +
            " points would take about " + std::to_string((bytes + (1u << 20) - 1) >> 20) +
            " MiB, more than max_memory_mb = " + std::to_string(options.max_memory_mb) +
            " (refused before decoding it); raise max_memory_mb where the machine "
            "has the memory, or give a smaller image");
  };
  const DepthImage depth = read_depth_png(frame.depth_path, within_budget);
  ColourImage colour;
  if (frame.colour_path) {
    // Compared before decoding: a colour image of another size is refused
    // without allocating for it.
    colour = read_colour_png(*frame.colour_path, [&](std::size_t width, std::size_t height) {
      if (width == depth.width && height == depth.height) return;
      throw InputError(path, 0,
                       "the colour image " + *frame.colour_path + " is " + std::to_string(width) +
                           " x " + std::to_string(height) + " pixels, the depth image " +
                           frame.depth_path + " " + std::to_string(depth.width) + " x " +
                           std::to_string(depth.height) +
                           ": a pixel's colour must be its depth's (register the colour to "
                           "the depth camera, or leave 'colour' out)");
    });
  }

  PointCloud cloud;
  ShiftedPositions shifted(options);
  const Eigen::Matrix3d rotation = frame.rotation.toRotationMatrix();
  std::size_t beyond_indoor = 0;
  double deepest = 0.0;
  for (std::size_t v = 0; v < depth.height; ++v) {
    for (std::size_t u = 0; u < depth.width; ++u) {
      const std::size_t pixel = v * depth.width + u;
      const std::uint16_t value = depth.values[pixel];
      if (value == 0) continue;  // no measurement
      // Pinhole back-projection; pixel (u, v)'s centre is at (u, v), as the
      // datasets' intrinsics (TUM's cx = 319.5 for 640 columns) take it.
      const double z = value / frame.depth_scale;
      beyond_indoor += z > kMaxIndoorDepthMetres ? 1 : 0;
      deepest = std::max(deepest, z);
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
  if (beyond_indoor > 0) {
    const auto number = [](double value) {
      std::string text;
      append_significant(text, value, 4);
      return text;
    };
    report.warnings.push_back(
        path + ": " + std::to_string(beyond_indoor) + " of " + std::to_string(cloud.size()) +
        " depths of " + frame.depth_path + " lie beyond " + number(kMaxIndoorDepthMetres) +
        " m (up to " + number(deepest) +
        " m), farther than indoor depth cameras measure: is depth_scale (" +
        number(frame.depth_scale) +
        " values a metre) the dataset's? SUN RGB-D's PNGs rotate each value's bits by three "
        "places: undo it first, (v >> 3) | (v << 13), in millimetres (docs/formats.md)");
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
