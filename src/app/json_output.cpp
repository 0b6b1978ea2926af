#include "occlusion/app/json_output.hpp"

#include <json/writer.h>

#include <cstdint>

namespace occlusion {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

// Bytes of the well-formed UTF-8 sequence starting at text[i], or 0
// (Unicode 15, table 3-7: no overlongs, no surrogates, at most U+10FFFF).
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[i + k]); };
  const std::uint8_t lead = byte(0);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  std::uint8_t low = 0x80;
  std::uint8_t high = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(1) < low || byte(1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(k) < 0x80 || byte(k) > 0xBF) return 0;
  }
  return length;
}

}  // namespace

std::string valid_utf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_sequence_length(text, i);
    if (length == 0) {
      out += kReplacement;
      ++i;
    } else {
      out.append(text, i, length);
      i += length;
    }
  }
  return out;
}

std::string printable_text(std::string_view text) {
  const std::string valid = valid_utf8(text);
  std::string out;
  out.reserve(valid.size());
  for (std::size_t i = 0; i < valid.size(); ++i) {
    const auto byte = static_cast<std::uint8_t>(valid[i]);
    // C1 controls (U+0080 to U+009F) are 0xC2 0x80 to 0xC2 0x9F in UTF-8.
    const bool c1 =
        byte == 0xC2 && i + 1 < valid.size() && static_cast<std::uint8_t>(valid[i + 1]) <= 0x9F;
    if ((byte < 0x20 && byte != '\t') || byte == 0x7F) {
      out += kReplacement;
    } else if (c1) {
      out += kReplacement;
      ++i;
    } else {
      out += valid[i];
    }
  }
  return out;
}

Json::Value with_valid_utf8(const Json::Value& value) {
  if (value.isString()) {
    const char* begin = nullptr;
    const char* end = nullptr;
    value.getString(&begin, &end);
    return Json::Value(valid_utf8(std::string_view(begin, static_cast<std::size_t>(end - begin))));
  }
  if (value.isArray()) {
    Json::Value array(Json::arrayValue);
    for (const Json::Value& item : value) array.append(with_valid_utf8(item));
    return array;
  }
  if (value.isObject()) {
    Json::Value object(Json::objectValue);
    for (auto it = value.begin(); it != value.end(); ++it) {
      object[valid_utf8(it.name())] = with_valid_utf8(*it);
    }
    return object;
  }
  return value;
}

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
  return Json::writeString(builder, with_valid_utf8(value));
}

}  // namespace occlusion
