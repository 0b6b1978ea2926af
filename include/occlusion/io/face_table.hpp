#pragma once
// The per-face table of -moc (MESH.moc.csv beside the PLY): a header line
// `face,group,area,samples,visible_fraction`, then one row per face, names
// quoted by csv_field, numbers with 9 significant digits (printf's %.9g, what a
// C++ stream with precision 9 writes).

#include <cstddef>
#include <string>
#include <vector>

#include "occlusion/core/mesh.hpp"

namespace occlusion {

// Written atomically (atomic_file.hpp). std::invalid_argument if `samples` or
// `visible_fraction` does not hold one value per face; OutputError if the file
// cannot be written.
void write_face_table(const std::string& path, const TriangleMesh& mesh,
                      const std::vector<std::size_t>& samples,
                      const std::vector<float>& visible_fraction);

}  // namespace occlusion
