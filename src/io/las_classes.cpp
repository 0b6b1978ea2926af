#include "las_classes.hpp"

#include <array>
#include <string_view>

namespace occlusion::detail {

std::string las_class_name(int id, int version_minor) {
  // LAS 1.4's table; "" where the standard reserves the id.
  static constexpr std::array<std::string_view, 19> kLas14 = {"never_classified",
                                                              "unclassified",
                                                              "ground",
                                                              "low_vegetation",
                                                              "medium_vegetation",
                                                              "high_vegetation",
                                                              "building",
                                                              "low_point_noise",
                                                              "",
                                                              "water",
                                                              "rail",
                                                              "road_surface",
                                                              "",
                                                              "wire_guard",
                                                              "wire_conductor",
                                                              "transmission_tower",
                                                              "wire_structure_connector",
                                                              "bridge_deck",
                                                              "high_noise"};
  std::string_view name;
  if (version_minor >= 4) {
    if (id < static_cast<int>(kLas14.size())) name = kLas14[static_cast<std::size_t>(id)];
  } else if (id == 8) {
    name = "model_key_point";
  } else if (id == 12) {
    name = "overlap";
  } else if (id <= 9) {
    name = kLas14[static_cast<std::size_t>(id)];
  }
  if (!name.empty()) return std::string(name);
  return (id >= 64 ? "user_" : "reserved_") + std::to_string(id);
}

}  // namespace occlusion::detail
