// The packets of a CompressedVector section, walked from its data offset to
// its end. Every packet states its length minus one, so each step moves on at
// least one byte: a packet cannot stall the walk.

#include "e57_section.hpp"

#include <array>

namespace occlusion::detail {
namespace {

constexpr std::uint64_t kSectionHeaderSize = 32;
constexpr unsigned char kCompressedVectorSection = 1;
constexpr unsigned char kIndexPacket = 0, kDataPacket = 1, kEmptyPacket = 2;
constexpr std::uint64_t kDataPacketHeaderSize = 6;

}  // namespace

E57Section read_compressed_vector(const E57Pages& pages, std::uint64_t physical_offset,
                                  std::size_t stream_count, const std::string& what) {
  const std::uint64_t start = pages.logical_of(physical_offset, what + "'s fileOffset");
  std::array<unsigned char, kSectionHeaderSize> header{};
  pages.copy(start, header.size(), header.data(), what + "'s section header");
  if (header[0] != kCompressedVectorSection) {
    pages.fail(physical_offset, what + ": the section there has id " + std::to_string(header[0]) +
                                    ", not 1 (a CompressedVector section)");
  }
  const std::uint64_t length = e57_u64(header.data() + 8);
  if (length < kSectionHeaderSize) {
    pages.fail(physical_offset + 8, what + ": section length " + std::to_string(length) +
                                        " is shorter than its 32-byte header");
  }
  pages.check_range(start, length, what + "'s section");
  const std::uint64_t end = start + length;
  E57Section section;
  section.start = start;
  section.end = end;
  std::vector<E57Stream>& streams = section.streams;
  streams.resize(stream_count);
  if (length == kSectionHeaderSize) return section;  // no packets: no records
  const std::uint64_t data_physical = e57_u64(header.data() + 16);
  std::uint64_t at = pages.logical_of(data_physical, what + "'s data offset");
  if (at < start + kSectionHeaderSize || at >= end) {
    pages.fail(physical_offset + 16, what + ": the data offset " + std::to_string(data_physical) +
                                         " lies outside its section");
  }
  std::vector<unsigned char> lengths;
  while (at < end) {
    const std::uint64_t physical = E57Pages::physical_of(at);
    std::array<unsigned char, kDataPacketHeaderSize> packet{};
    if (end - at < 4) {
      pages.fail(physical, what + ": " + std::to_string(end - at) +
                               " bytes at the section's end are too few for a packet");
    }
    pages.copy(at, 4, packet.data(), what + "'s packet");
    const std::uint64_t packet_length = std::uint64_t{e57_u16(packet.data() + 2)} + 1;
    if (packet_length > end - at) {
      pages.fail(physical, what + ": a packet of " + std::to_string(packet_length) +
                               " bytes runs past the section's end (" + std::to_string(end - at) +
                               " bytes left)");
    }
    if (packet[0] == kIndexPacket || packet[0] == kEmptyPacket) {
      at += packet_length;
      continue;
    }
    if (packet[0] != kDataPacket) {
      pages.fail(physical, what + ": unknown packet type " + std::to_string(packet[0]) +
                               " (0 index, 1 data, 2 empty)");
    }
    if (packet_length < kDataPacketHeaderSize) {
      pages.fail(physical, what + ": a data packet of " + std::to_string(packet_length) +
                               " bytes is shorter than its 6-byte header");
    }
    pages.copy(at, kDataPacketHeaderSize, packet.data(), what + "'s packet");
    const std::size_t count = e57_u16(packet.data() + 4);
    if (count != stream_count) {
      pages.fail(physical, what + ": a data packet has " + std::to_string(count) +
                               " bytestreams but the prototype has " +
                               std::to_string(stream_count) + " fields");
    }
    const std::uint64_t header_size = kDataPacketHeaderSize + 2 * std::uint64_t{count};
    if (header_size > packet_length) {
      pages.fail(physical, what + ": a data packet's " + std::to_string(count) +
                               " buffer lengths do not fit in its " +
                               std::to_string(packet_length) + " bytes");
    }
    lengths.resize(2 * count);
    pages.copy(at + kDataPacketHeaderSize, lengths.size(), lengths.data(), what + "'s packet");
    std::uint64_t buffer = at + header_size;
    for (std::size_t s = 0; s < count; ++s) {
      const std::uint64_t size = e57_u16(lengths.data() + 2 * s);
      if (size > at + packet_length - buffer) {
        pages.fail(physical, what + ": a data packet's buffers (" + std::to_string(size) +
                                 " bytes for field " + std::to_string(s) + ") overrun its " +
                                 std::to_string(packet_length) + " bytes");
      }
      pages.for_each_run(buffer, size, [&](const unsigned char* data, std::size_t run) {
        streams[s].runs.push_back({data, run});
      });
      streams[s].bytes += size;
      if (size > 0) ++streams[s].buffers;
      buffer += size;
    }
    at += packet_length;
  }
  return section;
}

}  // namespace occlusion::detail
