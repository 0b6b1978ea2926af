#pragma once
// Walks the body of a PLY file (ascii or binary, either byte order) element by
// element and hands every value to a sink, so that the cloud reader and the
// mesh reader share one decoder and one set of error messages: truncation,
// values that do not fit their type, data after the last element.

#include <cstddef>
#include <string>
#include <string_view>

#include "ply_header.hpp"

namespace occlusion::detail {

class PlySink {
 public:
  virtual ~PlySink() = default;
  // Whether the values of element `e` are wanted; others are only checked
  // (ascii) or skipped (binary, fixed-size records).
  virtual bool wants(std::size_t e) const = 0;
  // One value of property `p` of the current instance of element `e`; `item`
  // counts the items of a list property (0 for a scalar). Returns the problem
  // with the value, or "" if it is fine; the walker adds where it was.
  virtual std::string take(std::size_t e, std::size_t p, std::size_t item, double value) = 0;
  // The current instance of element `e` is complete. Returns a problem or "".
  virtual std::string end_instance(std::size_t e) = 0;
};

// InputError naming `path` and the line (ascii) or byte offset (binary).
void read_ply_body(std::string_view bytes, const std::string& path, const PlyHeader& header,
                   PlySink& sink);

}  // namespace occlusion::detail
