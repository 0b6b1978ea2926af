#include "ply_body.hpp"

#include <cstdint>
#include <cstring>
#include <limits>

#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {
namespace {

class PlyBodyReader {
 public:
  PlyBodyReader(std::string_view bytes, const std::string& path, const PlyHeader& header,
                PlySink& sink)
      : bytes_(bytes), path_(path), header_(header), sink_(sink) {}

  void run() {
    if (header_.encoding == PlyEncoding::kAscii) {
      read_ascii_body();
    } else {
      read_binary_body();
    }
  }

 private:
  // --- ascii: one element instance per line -------------------------------

  void read_ascii_body() {
    Lines lines(bytes_.substr(header_.body_offset), header_.body_line);
    std::string_view line;
    for (std::size_t e = 0; e < header_.elements.size(); ++e) {
      const PlyElement& element = header_.elements[e];
      for (std::size_t i = 0; i < element.count; ++i) {
        do {
          if (!lines.next(line)) {
            throw InputError(path_, lines.number(),
                             "the file ends after " + std::to_string(i) + " of the " +
                                 std::to_string(element.count) + " " + element.name +
                                 " lines the header declares");
          }
        } while (is_blank_line(line));
        read_ascii_instance(element, e, line, lines.number());
      }
    }
    while (lines.next(line)) {
      if (!is_blank_line(line)) {
        throw InputError(path_, lines.number(),
                         "data after the last element (the header declares " + counts_text() + ")");
      }
    }
  }

  void read_ascii_instance(const PlyElement& element, std::size_t e, std::string_view line,
                           std::size_t number) {
    const bool wanted = sink_.wants(e);
    Tokens tokens(line);
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      std::size_t items = 1;
      if (property.is_list) {
        const double count = ascii_value(tokens, property.count_type, element, property, number);
        if (count < 0) throw InputError(path_, number, "negative list length");
        items = static_cast<std::size_t>(count);
      }
      for (std::size_t k = 0; k < items; ++k) {
        const double value = ascii_value(tokens, property.type, element, property, number);
        if (wanted) {
          const std::string problem = sink_.take(e, p, k, value);
          if (!problem.empty()) throw InputError(path_, number, problem);
        }
      }
    }
    if (!tokens.next().empty()) {
      throw InputError(path_, number,
                       "more values than the " + element.name + " element's " +
                           std::to_string(element.properties.size()) + " properties");
    }
    if (wanted) {
      const std::string problem = sink_.end_instance(e);
      if (!problem.empty()) throw InputError(path_, number, problem);
    }
  }

  double ascii_value(Tokens& tokens, PlyType type, const PlyElement& element,
                     const PlyProperty& property, std::size_t number) {
    const std::string_view token = tokens.next();
    if (token.empty()) {
      throw InputError(
          path_, number,
          "the line ends before " + element.name + " property '" + property.name + "'");
    }
    double value = 0;
    if (is_integer(type)) {
      std::int64_t whole = 0;
      double lo = 0;
      double hi = 0;
      integer_range(type, lo, hi);
      if (!parse_whole_number(token, whole) || static_cast<double>(whole) < lo ||
          static_cast<double>(whole) > hi) {
        throw InputError(path_, number,
                         "property '" + property.name + "' value " + quoted(token) +
                             " is not an integer of its type");
      }
      value = static_cast<double>(whole);
    } else if (!parse_double(token, value)) {
      throw InputError(
          path_, number,
          "property '" + property.name + "' value " + quoted(token) + " is not a number");
    }
    return value;
  }

  // --- binary ------------------------------------------------------------

  void read_binary_body() {
    big_endian_ = header_.encoding == PlyEncoding::kBigEndian;
    std::size_t at = header_.body_offset;
    for (std::size_t e = 0; e < header_.elements.size(); ++e) {
      const PlyElement& element = header_.elements[e];
      check_fits(element, at);
      if (!sink_.wants(e) && fixed_size(element)) {
        at += element.count * record_size(element);
        continue;
      }
      for (std::size_t i = 0; i < element.count; ++i) {
        read_binary_instance(element, e, i, at);
      }
    }
    if (at != bytes_.size()) {
      throw InputError(path_, 0,
                       std::to_string(bytes_.size() - at) +
                           " bytes after the end of the data at byte " + std::to_string(at) +
                           " (the header declares " + counts_text() + ")");
    }
  }

  static bool fixed_size(const PlyElement& element) {
    for (const PlyProperty& property : element.properties) {
      if (property.is_list) return false;
    }
    return true;
  }

  // Bytes of one instance, counting each list as empty: a lower bound.
  static std::size_t record_size(const PlyElement& element) {
    std::size_t size = 0;
    for (const PlyProperty& property : element.properties) {
      size += type_size(property.is_list ? property.count_type : property.type);
    }
    return size;
  }

  // Reports truncation before reading (or allocating for) an element whose
  // instances cannot all fit in what is left of the file.
  void check_fits(const PlyElement& element, std::size_t at) const {
    const std::size_t size = record_size(element);
    if (size == 0) return;
    const std::size_t left = bytes_.size() - at;
    if (element.count <= left / size) return;
    throw InputError(path_, 0,
                     "truncated: the file ends at byte " + std::to_string(bytes_.size()) +
                         ", after " + std::to_string(left / size) + " of the " +
                         std::to_string(element.count) + " " + element.name +
                         " records the header declares (" + std::to_string(size) +
                         " bytes each from byte " + std::to_string(at) + ")");
  }

  void read_binary_instance(const PlyElement& element, std::size_t e, std::size_t index,
                            std::size_t& at) {
    const bool wanted = sink_.wants(e);
    const auto fail = [&](std::size_t start, const std::string& problem) {
      throw InputError(path_, 0,
                       "at byte " + std::to_string(start) + " (" + element.name + " " +
                           std::to_string(index) + "): " + problem);
    };
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (property.is_list) {
        const double count = binary_value(property.count_type, element, property, index, at);
        if (count < 0) {
          throw InputError(path_, 0,
                           "negative list length at byte " +
                               std::to_string(at - type_size(property.count_type)));
        }
        const std::size_t item = type_size(property.type);
        const auto items = static_cast<std::size_t>(count);
        if (items > (bytes_.size() - at) / item) truncated(element, property, index, at);
        if (!wanted) {
          at += items * item;
          continue;
        }
        for (std::size_t k = 0; k < items; ++k) {
          const std::size_t start = at;
          const double value = binary_value(property.type, element, property, index, at);
          const std::string problem = sink_.take(e, p, k, value);
          if (!problem.empty()) fail(start, problem);
        }
        continue;
      }
      const std::size_t start = at;
      const double value = binary_value(property.type, element, property, index, at);
      if (wanted) {
        const std::string problem = sink_.take(e, p, 0, value);
        if (!problem.empty()) fail(start, problem);
      }
    }
    if (wanted) {
      const std::string problem = sink_.end_instance(e);
      if (!problem.empty()) fail(at, problem);
    }
  }

  [[noreturn]] void truncated(const PlyElement& element, const PlyProperty& property,
                              std::size_t index, std::size_t at) const {
    throw InputError(path_, 0,
                     "truncated: the file ends at byte " + std::to_string(bytes_.size()) +
                         ", inside " + element.name + " " + std::to_string(index) + " of the " +
                         std::to_string(element.count) + " the header declares (property '" +
                         property.name + "' at byte " + std::to_string(at) + ")");
  }

  double binary_value(PlyType type, const PlyElement& element, const PlyProperty& property,
                      std::size_t index, std::size_t& at) const {
    const std::size_t size = type_size(type);
    if (size > bytes_.size() - at) truncated(element, property, index, at);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes_.data() + at);
    at += size;
    // Assembling the bits by shifts reads either byte order on any host.
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < size; ++k) {
      const std::size_t shift = big_endian_ ? 8 * (size - 1 - k) : 8 * k;
      bits |= std::uint64_t{data[k]} << shift;
    }
    switch (type) {
      case PlyType::kInt8:
        return static_cast<std::int8_t>(bits);
      case PlyType::kUint8:
        return static_cast<double>(bits);
      case PlyType::kInt16:
        return static_cast<std::int16_t>(bits);
      case PlyType::kUint16:
        return static_cast<double>(bits);
      case PlyType::kInt32:
        return static_cast<std::int32_t>(bits);
      case PlyType::kUint32:
        return static_cast<double>(bits);
      case PlyType::kFloat32: {
        const auto narrow = static_cast<std::uint32_t>(bits);
        float value;
        std::memcpy(&value, &narrow, sizeof value);
        return value;
      }
      case PlyType::kFloat64: {
        double value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
      }
    }
    return 0;
  }

  std::string counts_text() const {
    std::string text;
    for (const PlyElement& element : header_.elements) {
      if (!text.empty()) text += ", ";
      text += std::to_string(element.count) + " " + element.name;
    }
    return text;
  }

  std::string_view bytes_;
  const std::string& path_;
  const PlyHeader& header_;
  PlySink& sink_;
  bool big_endian_ = false;
};

}  // namespace

void read_ply_body(std::string_view bytes, const std::string& path, const PlyHeader& header,
                   PlySink& sink) {
  PlyBodyReader(bytes, path, header, sink).run();
}

}  // namespace occlusion::detail
