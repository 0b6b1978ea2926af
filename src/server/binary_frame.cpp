#include "occlusion/server/binary_frame.hpp"

#include <cstring>
#include <stdexcept>

#include "occlusion/server/protocol_error.hpp"

namespace occlusion::server {

namespace {

constexpr char kMagic[4] = {'O', 'C', 'C', 'B'};

// Explicit little-endian byte order, so the layout does not depend on the host.
template <class T>
void put(std::string& out, std::size_t offset, T value) {
  for (std::size_t b = 0; b < sizeof(T); ++b) {
    out[offset + b] = static_cast<char>(static_cast<std::uint64_t>(value) >> (8 * b) & 0xFF);
  }
}

template <class T>
T get(std::string_view in, std::size_t offset) {
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < sizeof(T); ++b) {
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[offset + b])) << (8 * b);
  }
  return static_cast<T>(value);
}

bool known_type(std::uint8_t type) {
  return type >= 1 && type <= 5;
}

}  // namespace

std::uint64_t FrameHeader::payload_bytes() const {
  return count * components * element_size(type);
}

std::size_t element_size(ElementType type) {
  switch (type) {
    case ElementType::kUint8:
      return 1;
    case ElementType::kUint16:
      return 2;
    case ElementType::kUint32:
    case ElementType::kInt32:
    case ElementType::kFloat32:
      return 4;
  }
  return 0;
}

const char* kind_name(FrameKind kind) {
  switch (kind) {
    case FrameKind::kPositions:
      return "positions";
    case FrameKind::kColours:
      return "colours";
    case FrameKind::kLabels:
      return "labels";
    case FrameKind::kInstances:
      return "instances";
    case FrameKind::kIndices:
      return "indices";
    case FrameKind::kFaceGroups:
      return "face_groups";
    case FrameKind::kFaceVisibleFraction:
      return "face_visible_fraction";
    case FrameKind::kVisibleCount:
      return "visible_count";
    case FrameKind::kEscapeDirections:
      return "escape_directions";
    case FrameKind::kPointClusters:
      return "point_clusters";
    case FrameKind::kCoveredBy:
      return "covered_by";
    case FrameKind::kUpload:
      return "upload";
  }
  return "unknown";
}

const char* type_name(ElementType type) {
  switch (type) {
    case ElementType::kUint8:
      return "uint8";
    case ElementType::kUint16:
      return "uint16";
    case ElementType::kUint32:
      return "uint32";
    case ElementType::kInt32:
      return "int32";
    case ElementType::kFloat32:
      return "float32";
  }
  return "unknown";
}

Json::Value describe(const FrameHeader& header) {
  Json::Value json(Json::objectValue);
  json["kind"] = kind_name(header.kind);
  json["type"] = type_name(header.type);
  json["components"] = header.components;
  json["count"] = Json::UInt64(header.count);
  json["item"] = header.item;
  return json;
}

Frame encode_frame(const FrameHeader& header, const void* payload, std::size_t bytes) {
  if (bytes != header.payload_bytes()) {
    throw std::invalid_argument("encode_frame: payload size disagrees with the header");
  }
  Frame frame;
  frame.header = header;
  std::string& out = frame.message;
  out.assign(kFrameHeaderSize + bytes, '\0');
  std::memcpy(out.data(), kMagic, sizeof kMagic);
  put<std::uint16_t>(out, 4, kFrameVersion);
  put<std::uint16_t>(out, 6, static_cast<std::uint16_t>(header.kind));
  put<std::uint32_t>(out, 8, header.request_id);
  put<std::uint8_t>(out, 12, static_cast<std::uint8_t>(header.type));
  put<std::uint8_t>(out, 13, header.components);
  put<std::uint64_t>(out, 16, header.count);
  put<std::uint32_t>(out, 24, header.item);
  // The payload is copied as the host stores it: every target we build for is
  // little-endian, which the protocol prescribes.
  static_assert(sizeof(float) == 4, "float32 payloads");
  if (bytes > 0) std::memcpy(out.data() + kFrameHeaderSize, payload, bytes);
  return frame;
}

FrameHeader decode_frame_header(std::string_view message) {
  const auto fail = [](const std::string& why) {
    throw ProtocolError("unexpected_binary", "binary message: " + why);
  };
  if (message.size() < kFrameHeaderSize) fail("shorter than the 32-byte header");
  if (std::memcmp(message.data(), kMagic, sizeof kMagic) != 0) fail("no 'OCCB' magic");
  if (get<std::uint16_t>(message, 4) != kFrameVersion) fail("unsupported version");
  const auto type = get<std::uint8_t>(message, 12);
  if (!known_type(type)) fail("unknown element type " + std::to_string(type));
  FrameHeader header;
  header.kind = static_cast<FrameKind>(get<std::uint16_t>(message, 6));
  header.request_id = *header_request_id(message);
  header.type = static_cast<ElementType>(type);
  header.components = get<std::uint8_t>(message, 13);
  header.count = get<std::uint64_t>(message, 16);
  header.item = get<std::uint32_t>(message, 24);
  const std::uint64_t payload = message.size() - kFrameHeaderSize;
  // Checked by division so that a huge count cannot overflow the product.
  const std::uint64_t element = header.components * element_size(header.type);
  if (element == 0 || payload % element != 0 || payload / element != header.count) {
    fail("payload of " + std::to_string(payload) + " bytes disagrees with the header");
  }
  return header;
}

std::optional<std::uint32_t> header_request_id(std::string_view message) {
  if (message.size() < kFrameHeaderSize) return std::nullopt;
  return get<std::uint32_t>(message, 8);
}

void set_request_id(std::string& message, std::uint32_t request_id) {
  if (message.size() < kFrameHeaderSize) throw std::invalid_argument("set_request_id: no header");
  put<std::uint32_t>(message, 8, request_id);
}

}  // namespace occlusion::server
