#pragma once
// Writes a room in the S3DIS layout:
//   ROOM_DIR/<name>.txt                      every point, x y z r g b
//   ROOM_DIR/Annotations/<class>_<k>.txt     one file per instance
// and, on request, its surfaces:
//   ROOM_DIR/<name>.obj                      one group <class>_<k> per instance
// (what the study's and the segmenter's virtual scans scan: the scanner
// needs surfaces, not points). Every file is written atomically.

#include <cstddef>
#include <string>
#include <vector>

#include "room_model.hpp"

namespace occlusion::room {

// ROOM_DIR is PARENT/<name>; returns the number of points written.
std::size_t write_s3dis_room(const std::string& parent, const std::string& name,
                             const std::vector<Instance>& instances);
// ROOM_DIR/<name>.obj from the instances' triangles; returns its path.
std::string write_room_mesh(const std::string& parent, const std::string& name,
                            const std::vector<Instance>& instances);

}  // namespace occlusion::room
