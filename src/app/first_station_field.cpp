#include "occlusion/app/first_station_field.hpp"

namespace occlusion {

ScalarField first_station_field(const std::vector<std::int32_t>& first_station) {
  ScalarField field{kFirstStationField, {}, true};
  field.values.reserve(first_station.size());
  for (const auto number : first_station) field.values.push_back(static_cast<float>(number));
  return field;
}

}  // namespace occlusion
