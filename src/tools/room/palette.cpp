#include "palette.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace occlusion::room {

namespace {

using Family = std::vector<Colour>;

const Family kNeutral{
    {232, 232, 226}, {214, 210, 200}, {190, 190, 186}, {245, 243, 238}, {170, 168, 160}};
const Family kPastel{{226, 206, 170}, {210, 190, 160}, {200, 214, 220}, {196, 210, 190}};
const Family kWood{{178, 138, 88}, {148, 98, 58}, {118, 80, 50}, {196, 160, 110}, {90, 62, 40}};
const Family kDark{{38, 38, 42}, {58, 60, 72}, {70, 70, 70}, {30, 40, 60}};
const Family kFabric{{140, 40, 40}, {60, 90, 140}, {90, 120, 70}, {160, 130, 100}, {110, 110, 120}};
const Family kBright{{196, 70, 60}, {70, 120, 170}, {84, 140, 62}, {220, 180, 50}, {200, 200, 200}};

const std::map<std::string, std::vector<const Family*>>& families() {
  static const std::map<std::string, std::vector<const Family*>> table{
      {"ceiling", {&kNeutral, &kPastel}},
      {"floor", {&kWood, &kNeutral, &kDark, &kFabric}},
      {"wall", {&kNeutral, &kPastel}},
      {"beam", {&kNeutral, &kPastel, &kWood}},
      {"column", {&kNeutral, &kPastel, &kDark}},
      {"window", {&kNeutral, &kDark}},
      {"door", {&kWood, &kNeutral, &kDark, &kPastel}},
      {"table", {&kWood, &kNeutral, &kDark}},
      {"chair", {&kDark, &kFabric, &kWood, &kNeutral}},
      {"sofa", {&kFabric, &kDark, &kNeutral}},
      {"bookcase", {&kWood, &kNeutral, &kDark}},
      {"board", {&kNeutral, &kDark, &kFabric}},
      {"clutter", {&kNeutral, &kPastel, &kWood, &kDark, &kFabric, &kBright}},
  };
  return table;
}

std::size_t pick(Rng& rng, std::size_t count) {
  return std::min(count - 1, static_cast<std::size_t>(rng.uniform() * static_cast<double>(count)));
}

}  // namespace

Colour object_colour(const std::string& class_name, Rng& rng) {
  const auto found = families().find(class_name);
  if (found == families().end()) throw std::logic_error("no palette for class " + class_name);
  const Family& family = *found->second[pick(rng, found->second.size())];
  Colour colour = family[pick(rng, family.size())];
  for (int& channel : colour) {
    channel =
        std::clamp(channel + static_cast<int>(std::lround(rng.uniform() * 50.0 - 25.0)), 0, 255);
  }
  return colour;
}

}  // namespace occlusion::room
