#pragma once
// The per-point field "which station saw this point first", written by plan
// (its targets, by the stations' rank) and -fscan (its points, by the
// viewpoints' order) under one name.

#include <cstdint>
#include <vector>

#include "occlusion/io/cloud_io.hpp"

namespace occlusion {

// The field's name in the written clouds (PLY scalar_first_station, PCD
// first_station): the number (from 1) of the first station that sees the
// point, -1 for none; Python's and the server's covered_by. Not
// "covered_by": CloudCompare's PLY reader takes any property whose name
// holds "red" for the red channel (docs/plan.md).
inline constexpr const char* kFirstStationField = "first_station";

// An int field of those numbers, one per point.
ScalarField first_station_field(const std::vector<std::int32_t>& first_station);

}  // namespace occlusion
