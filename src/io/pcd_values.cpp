#include "pcd_values.hpp"

#include <cstring>
#include <limits>

namespace occlusion::detail {

using Field = pcl::PCLPointField;

bool is_known_type(std::uint8_t datatype) {
  switch (datatype) {
    case Field::BOOL:
    case Field::INT8:
    case Field::UINT8:
    case Field::INT16:
    case Field::UINT16:
    case Field::INT32:
    case Field::UINT32:
    case Field::INT64:
    case Field::UINT64:
    case Field::FLOAT32:
    case Field::FLOAT64:
      return true;
    default:
      return false;
  }
}

bool is_integer_type(std::uint8_t datatype) {
  return datatype != Field::FLOAT32 && datatype != Field::FLOAT64;
}

std::size_t field_size(std::uint8_t datatype) {
  switch (datatype) {
    case Field::INT16:
    case Field::UINT16:
      return 2;
    case Field::INT32:
    case Field::UINT32:
    case Field::FLOAT32:
      return 4;
    case Field::INT64:
    case Field::UINT64:
    case Field::FLOAT64:
      return 8;
    default:
      return 1;
  }
}

double load_value(const std::uint8_t* at, std::uint8_t datatype) {
  auto load = [at](auto value) {
    std::memcpy(&value, at, sizeof value);
    return static_cast<double>(value);
  };
  switch (datatype) {
    case Field::BOOL:
      return load(std::uint8_t{});
    case Field::INT8:
      return load(std::int8_t{});
    case Field::UINT8:
      return load(std::uint8_t{});
    case Field::INT16:
      return load(std::int16_t{});
    case Field::UINT16:
      return load(std::uint16_t{});
    case Field::INT32:
      return load(std::int32_t{});
    case Field::UINT32:
      return load(std::uint32_t{});
    case Field::INT64:
      return load(std::int64_t{});
    case Field::UINT64:
      return load(std::uint64_t{});
    case Field::FLOAT32:
      return load(float{});
    case Field::FLOAT64:
      return load(double{});
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

void store_value(std::uint8_t* at, std::uint8_t datatype, double value) {
  auto store = [at](auto typed) { std::memcpy(at, &typed, sizeof typed); };
  switch (datatype) {
    case Field::BOOL:
    case Field::UINT8:
      return store(static_cast<std::uint8_t>(value));
    case Field::INT8:
      return store(static_cast<std::int8_t>(value));
    case Field::INT16:
      return store(static_cast<std::int16_t>(value));
    case Field::UINT16:
      return store(static_cast<std::uint16_t>(value));
    case Field::INT32:
      return store(static_cast<std::int32_t>(value));
    case Field::UINT32:
      return store(static_cast<std::uint32_t>(value));
    case Field::INT64:
      return store(static_cast<std::int64_t>(value));
    case Field::UINT64:
      return store(static_cast<std::uint64_t>(value));
    case Field::FLOAT32:
      return store(static_cast<float>(value));
    default:
      return store(value);
  }
}

bool integer_fits(std::uint8_t datatype, std::int64_t value) {
  switch (datatype) {
    case Field::BOOL:
      return value == 0 || value == 1;
    case Field::INT8:
      return value >= -128 && value <= 127;
    case Field::UINT8:
      return value >= 0 && value <= 255;
    case Field::INT16:
      return value >= -32768 && value <= 32767;
    case Field::UINT16:
      return value >= 0 && value <= 65535;
    case Field::INT32:
      return value >= std::numeric_limits<std::int32_t>::min() &&
             value <= std::numeric_limits<std::int32_t>::max();
    case Field::UINT32:
      return value >= 0 && value <= std::numeric_limits<std::uint32_t>::max();
    case Field::UINT64:
      return value >= 0;
    default:
      return true;
  }
}

bool is_packed_colour(const Field& field) {
  return (field.name == "rgb" || field.name == "rgba") && field.count == 1 &&
         (field.datatype == Field::FLOAT32 || field.datatype == Field::UINT32 ||
          field.datatype == Field::INT32);
}

}  // namespace occlusion::detail
