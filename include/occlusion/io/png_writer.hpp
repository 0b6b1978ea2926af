#pragma once
// A 16-bit greyscale PNG, as depth cameras store their depth images (TUM,
// ScanNet, Redwood), written with libpng: the image a depth-frame descriptor
// names (docs/formats.md, Depth frames).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion {

// `values` row by row, width x height of them. std::invalid_argument for a
// size that disagrees; OutputError naming `path` if it cannot be written.
void write_depth_png(const std::string& path, std::size_t width, std::size_t height,
                     const std::vector<std::uint16_t>& values);

}  // namespace occlusion
