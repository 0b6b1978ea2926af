#pragma once
// A label file: one integer label per line, line k for point k of a cloud
// stored elsewhere. This is how the ScanNet benchmark takes predictions and
// how most networks dump them (numpy savetxt):
//
//   # optional comment lines
//   0
//   1
//   25
//   -1            <- no label
//
// Whole numbers, written `3` or `3.000000`; -1 is no label, other negative
// values and values beyond int32 are errors. Blank lines and lines starting
// with `#` (numpy loadtxt) or `//` (as in text clouds) are skipped; a line
// holding more than one number is an error, since it is probably a cloud.
// CRLF and a UTF-8 byte-order mark are accepted.

#include <cstdint>
#include <string>
#include <vector>

namespace occlusion {

// InputError with the 1-based line for a bad value, and for a file with no labels.
std::vector<std::int32_t> read_label_file(const std::string& path);

// One label per line, no header. OutputError if the file cannot be written;
// written atomically (atomic_file.hpp).
void write_label_file(const std::string& path, const std::vector<std::int32_t>& labels);

// Whether `path` names a label file rather than a cloud: the extension .labels
// or .label, or a .txt whose first data line holds one number (a text cloud has
// at least three). InputError if a .txt cannot be read.
bool is_label_file(const std::string& path);

}  // namespace occlusion
