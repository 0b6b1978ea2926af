// The E57 XML section, parsed with pugixml, into the scans the reader needs.
// Every element is named in errors by its path from the root
// (data3D/0/pose/rotation/w), so a user can find it in the file's XML.

#include <pugixml.hpp>

#include <cmath>
#include <limits>

#include "e57_scan.hpp"
#include "occlusion/io/input_error.hpp"
#include "text_tokens.hpp"

namespace occlusion::detail {
namespace {

class XmlReader {
 public:
  explicit XmlReader(const std::string& path) : path_(path) {}

  [[noreturn]] void fail(const std::string& element, const std::string& reason) const {
    throw InputError(path_, 0, "E57 XML, element '" + element + "': " + reason);
  }

  std::string type_of(const pugi::xml_node& node) const { return node.attribute("type").value(); }

  void expect_type(const pugi::xml_node& node, const std::string& element,
                   std::initializer_list<const char*> types) const {
    const std::string type = type_of(node);
    std::string allowed;
    for (const char* candidate : types) {
      if (type == candidate) return;
      allowed += (allowed.empty() ? "" : " or ") + std::string(candidate);
    }
    fail(element, "has type '" + type + "', expected " + allowed);
  }

  // An attribute holding a whole number; `fallback` when absent.
  std::int64_t integer_attribute(const pugi::xml_node& node, const std::string& element,
                                 const char* name, std::int64_t fallback) const {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) return fallback;
    std::int64_t value = 0;
    if (!parse_whole_number(trimmed(attribute.value()), value)) {
      fail(element, std::string("attribute ") + name + "=" + quoted(attribute.value()) +
                        " is not a whole number");
    }
    return value;
  }

  double real_attribute(const pugi::xml_node& node, const std::string& element, const char* name,
                        double fallback) const {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) return fallback;
    double value = 0;
    if (!parse_double(trimmed(attribute.value()), value) || !std::isfinite(value)) {
      fail(element,
           std::string("attribute ") + name + "=" + quoted(attribute.value()) + " is not a number");
    }
    return value;
  }

  // The value of an Integer, ScaledInteger or Float element (empty text is
  // E57's default, 0).
  double number(const pugi::xml_node& node, const std::string& element) const {
    expect_type(node, element, {"Float", "Integer", "ScaledInteger"});
    const std::string_view text = trimmed(node.child_value());
    const std::string type = type_of(node);
    if (type == "Float") {
      double value = 0;
      if (!text.empty() && (!parse_double(text, value) || !std::isfinite(value))) {
        fail(element, "value " + quoted(text) + " is not a number");
      }
      return value;
    }
    std::int64_t raw = 0;
    if (!text.empty() && !parse_whole_number(text, raw)) {
      fail(element, "value " + quoted(text) + " is not a whole number");
    }
    if (type == "Integer") return static_cast<double>(raw);
    return static_cast<double>(raw) * real_attribute(node, element, "scale", 1.0) +
           real_attribute(node, element, "offset", 0.0);
  }

  // A child number, or `fallback` when the child is absent.
  double child_number(const pugi::xml_node& parent, const std::string& element, const char* name,
                      double fallback) const {
    const pugi::xml_node child = parent.child(name);
    if (!child) return fallback;
    return number(child, element + "/" + name);
  }

  std::string child_string(const pugi::xml_node& parent, const std::string& element,
                           const char* name) const {
    const pugi::xml_node child = parent.child(name);
    if (!child) return "";
    expect_type(child, element + "/" + name, {"String"});
    return std::string(trimmed(child.child_value()));
  }

  std::optional<E57Range> range(const pugi::xml_node& parent, const std::string& element,
                                const char* minimum, const char* maximum) const {
    if (!parent || (!parent.child(minimum) && !parent.child(maximum))) return std::nullopt;
    E57Range range{child_number(parent, element, minimum, 0.0),
                   child_number(parent, element, maximum, 0.0)};
    if (!(range.maximum >= range.minimum)) {
      fail(element, std::string(maximum) + " is below " + minimum);
    }
    return range;
  }

  E57Scan scan(const pugi::xml_node& node, std::size_t index) const {
    E57Scan scan;
    scan.element = "data3D/" + std::to_string(index);
    expect_type(node, scan.element, {"Structure"});
    scan.name = child_string(node, scan.element, "name");
    if (scan.name.empty()) scan.name = child_string(node, scan.element, "guid");
    if (scan.name.empty()) scan.name = "scan_" + std::to_string(index);
    read_pose(node.child("pose"), scan);
    read_limits(node, scan);
    read_points(node, scan);
    return scan;
  }

 private:
  static std::string_view trimmed(std::string_view text) {
    while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
    return text;
  }

  void read_pose(const pugi::xml_node& pose, E57Scan& scan) const {
    if (!pose) return;
    const std::string element = scan.element + "/pose";
    expect_type(pose, element, {"Structure"});
    if (const pugi::xml_node rotation = pose.child("rotation")) {
      const std::string at = element + "/rotation";
      expect_type(rotation, at, {"Structure"});
      Eigen::Quaterniond q(
          child_number(rotation, at, "w", 1.0), child_number(rotation, at, "x", 0.0),
          child_number(rotation, at, "y", 0.0), child_number(rotation, at, "z", 0.0));
      // A unit quaternion by the standard; writers print it to 7 to 17
      // digits. Anything further off is no rotation we can trust.
      const double norm = q.norm();
      if (!(std::fabs(norm - 1.0) <= 1e-3)) {
        fail(at, "is not a unit quaternion (norm " + std::to_string(norm) +
                     "); a pose's rotation must be w, x, y, z of norm 1");
      }
      scan.rotation = q.normalized();
    }
    if (const pugi::xml_node translation = pose.child("translation")) {
      const std::string at = element + "/translation";
      expect_type(translation, at, {"Structure"});
      scan.translation = {child_number(translation, at, "x", 0.0),
                          child_number(translation, at, "y", 0.0),
                          child_number(translation, at, "z", 0.0)};
    }
  }

  void read_limits(const pugi::xml_node& node, E57Scan& scan) const {
    const pugi::xml_node intensity = node.child("intensityLimits");
    scan.intensity_limits =
        range(intensity, scan.element + "/intensityLimits", "intensityMinimum", "intensityMaximum");
    const pugi::xml_node colour = node.child("colorLimits");
    const std::string at = scan.element + "/colorLimits";
    const auto red = range(colour, at, "colorRedMinimum", "colorRedMaximum");
    const auto green = range(colour, at, "colorGreenMinimum", "colorGreenMaximum");
    const auto blue = range(colour, at, "colorBlueMinimum", "colorBlueMaximum");
    if (red && green && blue) scan.colour_limits = std::array<E57Range, 3>{*red, *green, *blue};
    const pugi::xml_node bounds = node.child("indexBounds");
    const std::string index_at = scan.element + "/indexBounds";
    scan.row_bounds = range(bounds, index_at, "rowMinimum", "rowMaximum");
    scan.column_bounds = range(bounds, index_at, "columnMinimum", "columnMaximum");
  }

  void read_points(const pugi::xml_node& node, E57Scan& scan) const {
    const std::string element = scan.element + "/points";
    const pugi::xml_node points = node.child("points");
    if (!points) fail(scan.element, "has no 'points'");
    expect_type(points, element, {"CompressedVector"});
    const std::int64_t offset = integer_attribute(points, element, "fileOffset", -1);
    const std::int64_t count = integer_attribute(points, element, "recordCount", -1);
    if (offset < 0) fail(element, "has no fileOffset");
    if (count < 0) fail(element, "has no recordCount (or a negative one)");
    scan.section_offset = static_cast<std::uint64_t>(offset);
    scan.record_count = static_cast<std::uint64_t>(count);
    const pugi::xml_node prototype = points.child("prototype");
    if (!prototype) fail(element, "has no prototype");
    add_fields(prototype, element + "/prototype", "", 0, scan);
    check_codecs(points.child("codecs"), element + "/codecs");
  }

  // The prototype's leaves, depth first: the order of the bytestreams. Real
  // prototypes nest a level or two; the limit keeps a crafted file from
  // exhausting the stack.
  void add_fields(const pugi::xml_node& node, const std::string& element, const std::string& name,
                  int depth, E57Scan& scan) const {
    constexpr int kMaxDepth = 16;
    const std::string type = type_of(node);
    if (type == "Structure" || type == "Vector") {
      if (depth > kMaxDepth) fail(element, "nests Structures more than 16 deep");
      for (const pugi::xml_node& child : node.children()) {
        if (child.type() != pugi::node_element) continue;
        add_fields(child, element + "/" + child.name(),
                   name.empty() ? child.name() : name + "/" + child.name(), depth + 1, scan);
      }
      return;
    }
    E57Field field;
    field.name = name;
    if (type == "Float") {
      field.kind = E57Field::Kind::kFloat;
      const std::string precision = node.attribute("precision").value();
      if (precision != "" && precision != "single" && precision != "double") {
        fail(element, "precision '" + precision + "' is neither single nor double");
      }
      field.single = precision == "single";
      field.bits = field.single ? 32 : 64;
    } else if (type == "Integer" || type == "ScaledInteger") {
      field.kind = type == "Integer" ? E57Field::Kind::kInteger : E57Field::Kind::kScaledInteger;
      field.minimum =
          integer_attribute(node, element, "minimum", std::numeric_limits<std::int64_t>::min());
      field.maximum =
          integer_attribute(node, element, "maximum", std::numeric_limits<std::int64_t>::max());
      if (field.maximum < field.minimum) fail(element, "maximum is below minimum");
      if (field.kind == E57Field::Kind::kScaledInteger) {
        field.scale = real_attribute(node, element, "scale", 1.0);
        field.offset = real_attribute(node, element, "offset", 0.0);
        if (field.scale == 0) fail(element, "scale is 0");
      }
      const std::uint64_t span =
          static_cast<std::uint64_t>(field.maximum) - static_cast<std::uint64_t>(field.minimum);
      field.bits = 0;
      for (std::uint64_t rest = span; rest != 0; rest >>= 1) ++field.bits;
    } else {
      fail(element,
           "has type '" + type + "'; only Integer, ScaledInteger and Float point fields are read");
    }
    scan.fields.push_back(std::move(field));
  }

  // An empty codecs vector means the bitPackCodec for every field; an entry
  // naming anything else is a compression we cannot decode.
  void check_codecs(const pugi::xml_node& codecs, const std::string& element) const {
    if (!codecs) return;
    std::size_t k = 0;
    for (const pugi::xml_node& codec : codecs.children()) {
      if (codec.type() != pugi::node_element) continue;
      const std::string at = element + "/" + std::to_string(k++);
      for (const pugi::xml_node& part : codec.children()) {
        if (part.type() != pugi::node_element) continue;
        const std::string name = part.name();
        if (name == "inputs" || name == "bitPackCodec") continue;
        fail(at, "uses the codec '" + name + "'; only the bitPackCodec is read");
      }
    }
  }

  const std::string& path_;
};

std::size_t element_children(const pugi::xml_node& node) {
  std::size_t count = 0;
  for (const pugi::xml_node& child : node.children()) count += child.type() == pugi::node_element;
  return count;
}

}  // namespace

int E57Scan::field(std::string_view field_name) const {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].name == field_name) return static_cast<int>(i);
  }
  return -1;
}

std::vector<E57Scan> parse_e57_xml(std::string_view xml, const std::string& path) {
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(xml.data(), xml.size());
  if (!parsed) {
    throw InputError(path, 0,
                     "E57 XML section, at character " + std::to_string(parsed.offset) + ": " +
                         parsed.description());
  }
  const XmlReader reader(path);
  const pugi::xml_node root = document.child("e57Root");
  if (!root) reader.fail("e57Root", "is missing: the XML section is not an E57 tree");
  const pugi::xml_node data3d = root.child("data3D");
  if (!data3d || element_children(data3d) == 0) {
    const pugi::xml_node images = root.child("images2D");
    if (images && element_children(images) > 0) {
      reader.fail("data3D", "the file holds only images (" +
                                std::to_string(element_children(images)) +
                                " in images2D) and no 3D scan: there are no points to read");
    }
    reader.fail("data3D", "the file holds no 3D scan (data3D is empty or missing)");
  }
  std::vector<E57Scan> scans;
  for (const pugi::xml_node& child : data3d.children()) {
    if (child.type() != pugi::node_element) continue;
    scans.push_back(reader.scan(child, scans.size()));
  }
  return scans;
}

}  // namespace occlusion::detail
