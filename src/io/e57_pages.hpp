#pragma once
// The E57 physical layer (ASTM E2807): a 48-byte file header, then pages of
// 1024 bytes whose last 4 bytes are a CRC-32C of the other 1020. The XML and
// the binary sections are byte streams laid over the pages' 1020-byte
// payloads end to end ("logical" offsets); the file header, the XML and the
// section headers give "physical" offsets, which count the checksums too.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace occlusion::detail {

inline constexpr std::uint64_t kE57PageSize = 1024;
inline constexpr std::uint64_t kE57PagePayload = 1020;
inline constexpr std::uint64_t kE57HeaderSize = 48;

struct E57Header {
  std::uint32_t major = 0, minor = 0;
  std::uint64_t physical_length = 0;
  std::uint64_t xml_offset = 0;  // physical
  std::uint64_t xml_length = 0;  // logical bytes
  std::uint64_t page_size = 0;
};

// A view of the file's bytes (which must outlive it) whose header and page
// checksums have been checked. Every failure is an InputError naming `path`
// and the physical byte offset.
class E57Pages {
 public:
  E57Pages(std::string_view bytes, std::string path);

  const E57Header& header() const { return header_; }
  const std::string& path() const { return path_; }
  std::uint64_t logical_size() const { return pages_ * kE57PagePayload; }

  // The logical offset of a physical one that `what` gives; InputError if it
  // lies in a checksum or past the end.
  std::uint64_t logical_of(std::uint64_t physical, const std::string& what) const;
  static std::uint64_t physical_of(std::uint64_t logical) {
    return logical / kE57PagePayload * kE57PageSize + logical % kE57PagePayload;
  }

  // Logical bytes [at, at + size): InputError naming `what` unless they lie
  // in the file (checked before anything is allocated).
  void copy(std::uint64_t at, std::size_t size, unsigned char* out, const std::string& what) const;
  std::string read(std::uint64_t at, std::uint64_t size, const std::string& what) const;
  // Calls visit(pointer, length) for each run of [at, at + size) within one
  // page, in order. The range must have been checked (check_range).
  template <class Visit>
  void for_each_run(std::uint64_t at, std::uint64_t size, Visit&& visit) const {
    while (size > 0) {
      const std::uint64_t in_page = kE57PagePayload - at % kE57PagePayload;
      const std::uint64_t run = size < in_page ? size : in_page;
      visit(data_ + physical_of(at), static_cast<std::size_t>(run));
      at += run;
      size -= run;
    }
  }
  void check_range(std::uint64_t at, std::uint64_t size, const std::string& what) const;

  [[noreturn]] void fail(std::uint64_t physical, const std::string& reason) const;

 private:
  void read_header(std::string_view bytes);
  void check_pages() const;

  std::string path_;
  const unsigned char* data_ = nullptr;
  std::uint64_t pages_ = 0;
  E57Header header_;
};

// Little-endian integers as E57 stores them.
std::uint64_t e57_u64(const unsigned char* at);
std::uint32_t e57_u32(const unsigned char* at);
std::uint16_t e57_u16(const unsigned char* at);

}  // namespace occlusion::detail
