#include "occlusion/app/json_output.hpp"

#include <json/writer.h>

namespace occlusion {

Json::Value to_json(const Eigen::Vector3d& point) {
  Json::Value array(Json::arrayValue);
  for (int axis = 0; axis < 3; ++axis) array.append(point[axis]);
  return array;
}

Json::Value to_json(const std::vector<std::string>& strings) {
  Json::Value array(Json::arrayValue);
  for (const auto& s : strings) array.append(s);
  return array;
}

Json::Value to_json(const std::optional<double>& value) {
  return value ? Json::Value(*value) : Json::Value();
}

Json::Value to_json(const OctreeStats& stats) {
  Json::Value json(Json::objectValue);
  json["inner_nodes"] = Json::UInt64(stats.inner_nodes);
  json["leaves"] = Json::UInt64(stats.leaves);
  json["depth"] = stats.depth;
  json["largest_leaf"] = Json::UInt64(stats.largest_leaf);
  json["memory_bytes"] = Json::UInt64(stats.memory_bytes);
  return json;
}

std::string format_json(const Json::Value& value) {
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "  ";
  builder["emitUTF8"] = true;
  builder["precision"] = 15;
  return Json::writeString(builder, value);
}

}  // namespace occlusion
