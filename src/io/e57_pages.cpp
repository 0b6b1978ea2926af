// E57Pages: the file header and the page checksums, checked before any other
// part of the file is believed.

#include "e57_pages.hpp"

#include <cstdio>
#include <cstring>

#include "crc32c.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::detail {

std::uint64_t e57_u64(const unsigned char* at) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = value << 8 | at[i];
  return value;
}

std::uint32_t e57_u32(const unsigned char* at) {
  return static_cast<std::uint32_t>(at[0]) | static_cast<std::uint32_t>(at[1]) << 8 |
         static_cast<std::uint32_t>(at[2]) << 16 | static_cast<std::uint32_t>(at[3]) << 24;
}

std::uint16_t e57_u16(const unsigned char* at) {
  return static_cast<std::uint16_t>(at[0] | at[1] << 8);
}

E57Pages::E57Pages(std::string_view bytes, std::string path)
    : path_(std::move(path)), data_(reinterpret_cast<const unsigned char*>(bytes.data())) {
  read_header(bytes);
  check_pages();
}

void E57Pages::fail(std::uint64_t physical, const std::string& reason) const {
  throw InputError(path_, 0, "E57, at byte " + std::to_string(physical) + ": " + reason);
}

void E57Pages::read_header(std::string_view bytes) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), "ASTM-E57", 8) != 0) {
    throw InputError(path_, 0, "not an E57 file (it does not start with 'ASTM-E57')");
  }
  if (bytes.size() < kE57HeaderSize) {
    throw InputError(path_, 0,
                     "truncated E57 file: " + std::to_string(bytes.size()) +
                         " bytes, shorter than the 48-byte file header");
  }
  header_.major = e57_u32(data_ + 8);
  header_.minor = e57_u32(data_ + 12);
  header_.physical_length = e57_u64(data_ + 16);
  header_.xml_offset = e57_u64(data_ + 24);
  header_.xml_length = e57_u64(data_ + 32);
  header_.page_size = e57_u64(data_ + 40);
  if (header_.major != 1) {
    fail(8, "E57 version " + std::to_string(header_.major) + "." + std::to_string(header_.minor) +
                " is not read (only version 1.x)");
  }
  if (header_.page_size != kE57PageSize) {
    fail(40, "page size " + std::to_string(header_.page_size) + " is not read (only 1024)");
  }
  if (header_.physical_length != bytes.size()) {
    fail(16, "the header gives the file's length as " + std::to_string(header_.physical_length) +
                 " bytes but it has " + std::to_string(bytes.size()) +
                 (header_.physical_length > bytes.size() ? " (truncated)" : ""));
  }
  if (bytes.size() % kE57PageSize != 0) {
    fail(16, "the file's length, " + std::to_string(bytes.size()) +
                 " bytes, is not a whole number of 1024-byte pages (truncated)");
  }
  pages_ = bytes.size() / kE57PageSize;
  const std::uint64_t xml = logical_of(header_.xml_offset, "the XML section's offset");
  if (header_.xml_length == 0 || header_.xml_length > logical_size() - xml) {
    fail(32, "the XML section (" + std::to_string(header_.xml_length) + " bytes from byte " +
                 std::to_string(header_.xml_offset) + ") does not lie in the file");
  }
}

void E57Pages::check_pages() const {
  for (std::uint64_t page = 0; page < pages_; ++page) {
    const unsigned char* start = data_ + page * kE57PageSize;
    const std::uint32_t computed = crc32c(start, kE57PagePayload);
    const unsigned char* stored = start + kE57PagePayload;
    // Stored most significant byte first, unlike every other E57 integer.
    const std::uint32_t expected = static_cast<std::uint32_t>(stored[0]) << 24 |
                                   static_cast<std::uint32_t>(stored[1]) << 16 |
                                   static_cast<std::uint32_t>(stored[2]) << 8 | stored[3];
    if (computed != expected) {
      char text[64];
      std::snprintf(text, sizeof text, "0x%08x but its bytes give 0x%08x", expected, computed);
      fail(page * kE57PageSize, "page " + std::to_string(page) + " (bytes " +
                                    std::to_string(page * kE57PageSize) + " to " +
                                    std::to_string(page * kE57PageSize + kE57PageSize - 1) +
                                    ") is corrupt: its CRC-32C checksum is " + text);
    }
  }
}

std::uint64_t E57Pages::logical_of(std::uint64_t physical, const std::string& what) const {
  if (physical >= pages_ * kE57PageSize) {
    fail(physical, what + " lies past the end of the file (" +
                       std::to_string(pages_ * kE57PageSize) + " bytes)");
  }
  if (physical % kE57PageSize >= kE57PagePayload) {
    fail(physical, what + " points into a page's checksum");
  }
  return physical / kE57PageSize * kE57PagePayload + physical % kE57PageSize;
}

void E57Pages::check_range(std::uint64_t at, std::uint64_t size, const std::string& what) const {
  if (at > logical_size() || size > logical_size() - at) {
    fail(physical_of(at < logical_size() ? at : logical_size()),
         what + " (" + std::to_string(size) + " bytes) runs past the end of the file");
  }
}

void E57Pages::copy(std::uint64_t at, std::size_t size, unsigned char* out,
                    const std::string& what) const {
  check_range(at, size, what);
  for_each_run(at, size, [&](const unsigned char* run, std::size_t length) {
    std::memcpy(out, run, length);
    out += length;
  });
}

std::string E57Pages::read(std::uint64_t at, std::uint64_t size, const std::string& what) const {
  check_range(at, size, what);
  std::string text(static_cast<std::size_t>(size), '\0');
  copy(at, text.size(), reinterpret_cast<unsigned char*>(text.data()), what);
  return text;
}

}  // namespace occlusion::detail
