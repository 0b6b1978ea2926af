#include "e57_writer.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace occlusion::test {
namespace {

constexpr std::size_t kPayload = 1020, kPage = 1024;

// Bit by bit, deliberately unlike the reader's table or instruction.
std::uint32_t crc32c_bitwise(const unsigned char* data, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0x82F63B78u & (0u - (crc & 1u)));
  }
  return ~crc;
}

void put(std::string& out, std::size_t at, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i)
    out[at + static_cast<std::size_t>(i)] = static_cast<char>(value >> (8 * i));
}

void append(std::string& out, std::uint64_t value, int bytes) {
  out.append(static_cast<std::size_t>(bytes), '\0');
  put(out, out.size() - static_cast<std::size_t>(bytes), value, bytes);
}

std::uint64_t physical(std::uint64_t logical) {
  return logical / kPayload * kPage + logical % kPayload;
}

std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

unsigned bits_of(const E57FieldSpec& field) {
  switch (field.kind) {
    case E57FieldSpec::Kind::kSingle:
      return 32;
    case E57FieldSpec::Kind::kDouble:
      return 64;
    default: {
      unsigned bits = 0;
      for (auto span = static_cast<std::uint64_t>(field.maximum) -
                       static_cast<std::uint64_t>(field.minimum);
           span != 0; span >>= 1) {
        ++bits;
      }
      return bits;
    }
  }
}

std::size_t count_of(const E57FieldSpec& field) {
  const bool floating =
      field.kind == E57FieldSpec::Kind::kSingle || field.kind == E57FieldSpec::Kind::kDouble;
  return floating ? field.values.size() : field.raw.size();
}

// The field's bytestream: each value's bits, least significant first.
std::string bytestream(const E57FieldSpec& field) {
  const unsigned bits = bits_of(field);
  std::vector<bool> stream;
  for (std::size_t i = 0; i < count_of(field); ++i) {
    std::uint64_t word = 0;
    if (field.kind == E57FieldSpec::Kind::kSingle) {
      const auto value = static_cast<float>(field.values[i]);
      std::uint32_t narrow;
      std::memcpy(&narrow, &value, 4);
      word = narrow;
    } else if (field.kind == E57FieldSpec::Kind::kDouble) {
      std::memcpy(&word, &field.values[i], 8);
    } else {
      word = static_cast<std::uint64_t>(field.raw[i]) - static_cast<std::uint64_t>(field.minimum);
    }
    for (unsigned b = 0; b < bits; ++b) stream.push_back(((word >> b) & 1u) != 0);
  }
  std::string bytes((stream.size() + 7) / 8, '\0');
  for (std::size_t b = 0; b < stream.size(); ++b) {
    if (stream[b]) bytes[b / 8] = static_cast<char>(bytes[b / 8] | (1 << (b % 8)));
  }
  return bytes;
}

std::string field_xml(const E57FieldSpec& field) {
  std::string xml = "<" + field.name;
  switch (field.kind) {
    case E57FieldSpec::Kind::kSingle:
      xml += " type=\"Float\" precision=\"single\"";
      break;
    case E57FieldSpec::Kind::kDouble:
      xml += " type=\"Float\"";
      break;
    case E57FieldSpec::Kind::kInteger:
    case E57FieldSpec::Kind::kScaledInteger:
      xml += field.kind == E57FieldSpec::Kind::kInteger ? " type=\"Integer\""
                                                        : " type=\"ScaledInteger\"";
      xml += " minimum=\"" + std::to_string(field.minimum) + "\" maximum=\"" +
             std::to_string(field.maximum) + "\"";
      if (field.kind == E57FieldSpec::Kind::kScaledInteger) {
        xml += " scale=\"" + number(field.scale) + "\" offset=\"" + number(field.offset) + "\"";
      }
      break;
  }
  return xml + "/>\n";
}

// Appends the scan's CompressedVector section to `logical`; returns its
// physical offset.
std::uint64_t append_section(std::string& logical, const E57ScanSpec& scan) {
  while (logical.size() % 4 != 0) logical.push_back('\0');
  const std::size_t start = logical.size();
  logical.push_back('\x01');
  logical.append(31, '\0');
  const std::size_t data = logical.size();
  if (scan.filler_packets) {
    append(logical, 0x00030002, 4);  // empty packet, 4 bytes
    logical.push_back('\0');         // index packet, 16 bytes, no entries
    logical.push_back('\0');
    append(logical, 15, 2);
    logical.append(12, '\0');
  }
  std::vector<std::string> streams;
  for (const E57FieldSpec& field : scan.fields) streams.push_back(bytestream(field));
  const std::size_t packets = scan.packets == 0 ? 1 : scan.packets;
  for (std::size_t p = 0; p < packets; ++p) {
    std::vector<std::string> buffers;
    for (const std::string& stream : streams) {
      // Uneven cuts: packet p gets bytes [cut(p), cut(p + 1)), the last the rest.
      const auto cut = [&](std::size_t k) {
        return k >= packets ? stream.size() : stream.size() * k * k / (packets * packets);
      };
      buffers.push_back(stream.substr(cut(p), cut(p + 1) - cut(p)));
    }
    std::string packet;
    packet.push_back('\x01');
    packet.push_back('\0');
    append(packet, 0, 2);
    append(packet, buffers.size(), 2);
    for (const std::string& buffer : buffers) append(packet, buffer.size(), 2);
    for (const std::string& buffer : buffers) packet += buffer;
    while (packet.size() % 4 != 0) packet.push_back('\0');
    if (packet.size() > 65536) throw std::invalid_argument("e57 test writer: packet too large");
    put(packet, 2, packet.size() - 1, 2);
    logical += packet;
  }
  put(logical, start + 8, logical.size() - start, 8);
  put(logical, start + 16, physical(data), 8);
  return physical(start);
}

std::string scan_xml(const E57ScanSpec& scan, std::uint64_t offset) {
  std::string xml = "<vectorChild type=\"Structure\">\n";
  if (!scan.name.empty()) xml += "<name type=\"String\"><![CDATA[" + scan.name + "]]></name>\n";
  if (!scan.guid.empty()) xml += "<guid type=\"String\"><![CDATA[" + scan.guid + "]]></guid>\n";
  if (scan.rotation || scan.translation) {
    xml += "<pose type=\"Structure\">\n";
    if (scan.rotation) {
      const Eigen::Quaterniond& q = *scan.rotation;
      xml += "<rotation type=\"Structure\"><w type=\"Float\">" + number(q.w()) +
             "</w><x type=\"Float\">" + number(q.x()) + "</x><y type=\"Float\">" + number(q.y()) +
             "</y><z type=\"Float\">" + number(q.z()) + "</z></rotation>\n";
    }
    if (scan.translation) {
      const Eigen::Vector3d& t = *scan.translation;
      xml += "<translation type=\"Structure\"><x type=\"Float\">" + number(t.x()) +
             "</x><y type=\"Float\">" + number(t.y()) + "</y><z type=\"Float\">" + number(t.z()) +
             "</z></translation>\n";
    }
    xml += "</pose>\n";
  }
  xml += scan.extra_xml;
  const std::uint64_t records = scan.record_count
                                    ? *scan.record_count
                                    : (scan.fields.empty() ? 0 : count_of(scan.fields.front()));
  xml += "<points type=\"CompressedVector\" fileOffset=\"" + std::to_string(offset) +
         "\" recordCount=\"" + std::to_string(records) + "\">\n<prototype type=\"Structure\">\n";
  for (const E57FieldSpec& field : scan.fields) xml += field_xml(field);
  xml += "</prototype>\n<codecs type=\"Vector\" allowHeterogeneousChildren=\"1\">" +
         scan.codecs_xml + "</codecs>\n</points>\n</vectorChild>\n";
  return xml;
}

}  // namespace

E57FieldSpec e57_double(std::string name, std::vector<double> values) {
  E57FieldSpec field;
  field.name = std::move(name);
  field.kind = E57FieldSpec::Kind::kDouble;
  field.values = std::move(values);
  return field;
}

E57FieldSpec e57_single(std::string name, std::vector<double> values) {
  E57FieldSpec field = e57_double(std::move(name), std::move(values));
  field.kind = E57FieldSpec::Kind::kSingle;
  return field;
}

E57FieldSpec e57_integer(std::string name, std::int64_t minimum, std::int64_t maximum,
                         std::vector<std::int64_t> raw) {
  E57FieldSpec field;
  field.name = std::move(name);
  field.kind = E57FieldSpec::Kind::kInteger;
  field.minimum = minimum;
  field.maximum = maximum;
  field.raw = std::move(raw);
  return field;
}

E57FieldSpec e57_scaled(std::string name, std::int64_t minimum, std::int64_t maximum, double scale,
                        double offset, std::vector<std::int64_t> raw) {
  E57FieldSpec field = e57_integer(std::move(name), minimum, maximum, std::move(raw));
  field.kind = E57FieldSpec::Kind::kScaledInteger;
  field.scale = scale;
  field.offset = offset;
  return field;
}

void fix_e57_checksums(std::string& bytes) {
  for (std::size_t page = 0; page + kPage <= bytes.size(); page += kPage) {
    const std::uint32_t crc =
        crc32c_bitwise(reinterpret_cast<const unsigned char*>(bytes.data()) + page, kPayload);
    for (int i = 0; i < 4; ++i) {
      bytes[page + kPayload + static_cast<std::size_t>(i)] = static_cast<char>(crc >> (24 - 8 * i));
    }
  }
}

std::string e57_bytes(const E57FileSpec& spec) {
  std::string logical(48, '\0');
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<e57Root type=\"Structure\" "
      "xmlns=\"http://www.astm.org/COMMIT/E57/2010-e57-v1.0\">\n"
      "<formatName type=\"String\"><![CDATA[ASTM E57 3D Imaging Data File]]></formatName>\n"
      "<data3D type=\"Vector\" allowHeterogeneousChildren=\"1\">\n";
  for (const E57ScanSpec& scan : spec.scans) xml += scan_xml(scan, append_section(logical, scan));
  xml += "</data3D>\n<images2D type=\"Vector\" allowHeterogeneousChildren=\"1\">" +
         spec.images2d_xml + "</images2D>\n</e57Root>\n";
  const std::size_t xml_at = logical.size();
  logical += xml;
  const std::size_t pages = (logical.size() + kPayload - 1) / kPayload;
  logical.resize(pages * kPayload, '\0');
  std::memcpy(logical.data(), "ASTM-E57", 8);
  put(logical, 8, 1, 4);
  put(logical, 12, 0, 4);
  put(logical, 16, pages * kPage, 8);
  put(logical, 24, physical(xml_at), 8);
  put(logical, 32, xml.size(), 8);
  put(logical, 40, kPage, 8);
  std::string bytes;
  for (std::size_t page = 0; page < pages; ++page) {
    bytes += logical.substr(page * kPayload, kPayload);
    bytes.append(4, '\0');
  }
  fix_e57_checksums(bytes);
  return bytes;
}

void write_e57(const std::string& path, const E57FileSpec& spec) {
  const std::string bytes = e57_bytes(spec);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace occlusion::test
