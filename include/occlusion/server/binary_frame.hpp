#pragma once
// Bulk data on the wire (docs/protocol.md, "Binary frames"): a 32-byte
// little-endian header, then one tightly packed array. The payload starts at
// byte 32 so that the viewer can view it as a Float32Array without a copy.

#include <json/value.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace occlusion::server {

enum class FrameKind : std::uint16_t {
  kPositions = 1,
  kColours = 2,
  kLabels = 3,
  kInstances = 4,
  kIndices = 5,
  kFaceGroups = 6,
  kFaceVisibleFraction = 7,
  kVisibleCount = 8,
  kEscapeDirections = 9,
  kPointClusters = 10,
  kCoveredBy = 11,  // plan: per target, the first station's rank (int32, -1 none)
  kUpload = 100,
};

enum class ElementType : std::uint8_t {
  kUint8 = 1,
  kUint16 = 2,
  kUint32 = 3,
  kInt32 = 4,
  kFloat32 = 5,
};

constexpr std::size_t kFrameHeaderSize = 32;
constexpr std::uint16_t kFrameVersion = 1;

struct FrameHeader {
  FrameKind kind = FrameKind::kPositions;
  std::uint32_t request_id = 0;
  ElementType type = ElementType::kUint8;
  std::uint8_t components = 1;
  std::uint64_t count = 0;  // elements, each of `components` values
  std::uint32_t item = 0;   // which of several frames of one kind (viewpoint index)

  std::uint64_t payload_bytes() const;
};

// One encoded message and what it holds (for the reply's "frames" list).
struct Frame {
  FrameHeader header;
  std::string message;  // header + payload
};

std::size_t element_size(ElementType type);
const char* kind_name(FrameKind kind);
const char* type_name(ElementType type);

// {"kind": "positions", "type": "float32", "components": 3, "count": N, "item": 0}
Json::Value describe(const FrameHeader& header);

// `bytes` must equal header.payload_bytes() (std::invalid_argument otherwise).
Frame encode_frame(const FrameHeader& header, const void* payload, std::size_t bytes);

// Reads and checks a received message's header: its size, magic, version,
// element type and that the payload is exactly as long as it says. Throws
// ProtocolError("unexpected_binary").
FrameHeader decode_frame_header(std::string_view message);

// The request id a message's header names, read even when the rest of the
// header or the payload is wrong, so that a malformed upload is answered under
// its own id; nullopt for a message shorter than a header.
std::optional<std::uint32_t> header_request_id(std::string_view message);

// The request id lives in the header, so a cached frame is re-addressed in place.
void set_request_id(std::string& message, std::uint32_t request_id);

template <class T>
struct ElementTypeOf;
template <>
struct ElementTypeOf<std::uint8_t> : std::integral_constant<ElementType, ElementType::kUint8> {};
template <>
struct ElementTypeOf<std::uint16_t> : std::integral_constant<ElementType, ElementType::kUint16> {};
template <>
struct ElementTypeOf<std::uint32_t> : std::integral_constant<ElementType, ElementType::kUint32> {};
template <>
struct ElementTypeOf<std::int32_t> : std::integral_constant<ElementType, ElementType::kInt32> {};
template <>
struct ElementTypeOf<float> : std::integral_constant<ElementType, ElementType::kFloat32> {};

// A frame from `count * components` packed values of T.
template <class T>
Frame make_frame(FrameKind kind, const T* values, std::size_t count, std::uint8_t components,
                 std::uint32_t item = 0) {
  FrameHeader header;
  header.kind = kind;
  header.type = ElementTypeOf<T>::value;
  header.components = components;
  header.count = count;
  header.item = item;
  return encode_frame(header, values, count * components * sizeof(T));
}

}  // namespace occlusion::server
