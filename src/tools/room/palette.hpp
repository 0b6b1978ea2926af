#pragma once
// Object colours that do not encode the class: each class draws from
// several colour families, and each family serves several classes (walls,
// ceilings, columns and boards can all be off-white; tables, doors, floors
// and bookcases can all be wood), so colour alone cannot tell a segmenter
// which class a point is.

#include <string>

#include "occlusion/core/random.hpp"
#include "room_model.hpp"

namespace occlusion::room {

// One object's base colour: a family the class may take, a colour of that
// family, and a jitter of up to +-25 per channel.
Colour object_colour(const std::string& class_name, Rng& rng);

}  // namespace occlusion::room
