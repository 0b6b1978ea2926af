#pragma once
// Values of PCL point fields, read from and stored into PCLPointCloud2
// records in host byte order, which is how PCL keeps them.

#include <pcl/PCLPointField.h>

#include <cstddef>
#include <cstdint>

namespace occlusion::detail {

// Whether PCL has a type of this number (INT8 … FLOAT64, BOOL). PCL gives an
// unknown TYPE letter or a SIZE that does not go with it (F 1) a number that
// is none of these.
bool is_known_type(std::uint8_t datatype);
bool is_integer_type(std::uint8_t datatype);
std::size_t field_size(std::uint8_t datatype);
double load_value(const std::uint8_t* at, std::uint8_t datatype);
void store_value(std::uint8_t* at, std::uint8_t datatype, double value);
// Whether an integer read from text fits the field's type.
bool integer_fits(std::uint8_t datatype, std::int64_t value);
// A 4-byte `rgb` or `rgba` field holding 0x00RRGGBB (PCL's packing).
bool is_packed_colour(const pcl::PCLPointField& field);

}  // namespace occlusion::detail
