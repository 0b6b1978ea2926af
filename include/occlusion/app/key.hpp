#pragma once
// One declaration per key. A key's name, type, range, unit and meaning are
// written once, beside the request field it fills; its default is that
// field's initialiser. The config reader, the checks, the CLI options and
// their --help, the server's params and `hello`, the Python keyword arguments
// and every report's `parameters` block are derived from the declarations:
//
//   key("point_radius", &CloudOcclusionRequest::point_radius).positive().unit("m")
//       .doc("sphere radius of each point")
//
// Values travel as JSON whatever the face (command line text is converted by
// type first), so one check serves all faces; a failing check names the key as
// the user wrote it (`--point-radius`, `occlusion.point_cloud.point_radius`,
// `point_radius`).

#include <json/value.h>

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "occlusion/app/viewpoint_choice.hpp"

namespace occlusion {

enum class ValueType {
  kString,
  kPath,  // a string naming a file or folder (resolved against the config's folder)
  kNumber,
  kInteger,  // non-negative
  kBool,
  kStringList,
  kPathList,
  kIntegerList,
  kNumberList,
  kPointList,      // [[x, y, z], ...]
  kViewpointSets,  // [{"name", and "pattern" | "num_vp" | "viewpoints"}, ...]
  // [PATH | {"path": PATH, KEY: value, ...}, ...]: paths, each with values of
  // its own for some of the job's keys (KeyInfo::entry_keys), e.g. a study's
  // scenes with their own point radius.
  kPathEntries,
};

// What a key is, for checks, help and the faces. Face-neutral: no JSON here
// but the default value.
struct KeyInfo {
  std::string name;  // config key, snake_case
  ValueType type = ValueType::kString;
  std::string doc;
  std::string unit;
  std::string metavar;  // for --help, e.g. "N", "I/N"
  std::optional<double> min, max;
  bool min_exclusive = false;  // (min, max] instead of [min, max]
  bool allows_auto = false;    // the string "auto" is a value (held as null / unset)
  std::vector<std::string> choices;
  std::size_t max_items = 0;  // lists: at most this many items (0: no limit)
  std::string cli_name;       // "--point-radius" unless declared otherwise
  std::vector<std::string> cli_aliases;
  bool repeatable = false;      // CLI: each occurrence adds one item to a list
  bool output = false;          // names something the job writes (need not exist)
  std::string exclusive_group;  // keys of one group: at most one per source
  std::vector<std::pair<std::string, Json::Value>> implies;  // giving this key sets those
  Json::Value default_value;  // the request's initialiser (null: none)
  // kPathEntries: the keys an entry may hold besides "path", as the job
  // declares them (so an entry's value is checked as the key's own is).
  std::vector<KeyInfo> entry_keys;
};

// A type-erased setter and getter of one request field.
template <class R>
struct Key {
  KeyInfo info;
  std::function<void(R&, const Json::Value&)> set;  // value already checked
  std::function<Json::Value(const R&)> get;         // null: not in force
};

template <class R>
using Keys = std::vector<Key<R>>;

// -- value conversions between request fields and JSON ------------------------

namespace key_detail {

template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};

template <class T>
constexpr ValueType value_type() {
  if constexpr (std::is_same_v<T, bool>) {
    return ValueType::kBool;
  } else if constexpr (std::is_integral_v<T>) {
    return ValueType::kInteger;
  } else if constexpr (std::is_floating_point_v<T> || std::is_same_v<T, std::optional<double>>) {
    return ValueType::kNumber;
  } else if constexpr (std::is_same_v<T, std::string>) {
    return ValueType::kString;
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    return ValueType::kStringList;
  } else if constexpr (std::is_same_v<T, std::vector<int>>) {
    return ValueType::kIntegerList;
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    return ValueType::kNumberList;
  } else {
    static_assert(sizeof(T) == 0, "no ValueType for this field type");
  }
}

template <class T>
T from_json(const Json::Value& value) {
  if constexpr (std::is_same_v<T, bool>) {
    return value.asBool();
  } else if constexpr (std::is_integral_v<T>) {
    return static_cast<T>(value.asUInt64());
  } else if constexpr (std::is_floating_point_v<T>) {
    return static_cast<T>(value.asDouble());
  } else if constexpr (std::is_same_v<T, std::optional<double>>) {
    if (value.isNull() || value.isString()) return std::nullopt;  // "auto"
    return value.asDouble();
  } else if constexpr (std::is_same_v<T, std::string>) {
    return value.asString();
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    std::vector<std::string> items;
    for (const auto& item : value) items.push_back(item.asString());
    return items;
  } else if constexpr (std::is_same_v<T, std::vector<int>>) {
    std::vector<int> items;
    for (const auto& item : value) items.push_back(item.asInt());
    return items;
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    std::vector<double> items;
    for (const auto& item : value) items.push_back(item.asDouble());
    return items;
  }
}

template <class T>
Json::Value to_json(const T& field) {
  if constexpr (std::is_same_v<T, bool>) {
    return Json::Value(field);
  } else if constexpr (std::is_integral_v<T>) {
    return Json::Value(static_cast<Json::UInt64>(field));
  } else if constexpr (std::is_floating_point_v<T>) {
    return Json::Value(static_cast<double>(field));
  } else if constexpr (std::is_same_v<T, std::optional<double>>) {
    return field ? Json::Value(*field) : Json::Value("auto");
  } else if constexpr (std::is_same_v<T, std::string>) {
    return Json::Value(field);
  } else {
    Json::Value list(Json::arrayValue);
    for (const auto& item : field) list.append(item);
    return list;
  }
}

}  // namespace key_detail

// -- the declaration builder ---------------------------------------------------

template <class R>
class KeyBuilder {
 public:
  explicit KeyBuilder(Key<R> key) : key_(std::move(key)) {}

  KeyBuilder& doc(std::string text) {
    return edit([&](KeyInfo& i) { i.doc = std::move(text); });
  }
  KeyBuilder& unit(std::string text) {
    return edit([&](KeyInfo& i) { i.unit = std::move(text); });
  }
  KeyBuilder& metavar(std::string text) {
    return edit([&](KeyInfo& i) { i.metavar = std::move(text); });
  }
  // Inclusive bounds.
  KeyBuilder& range(double lo, double hi) {
    return edit([&](KeyInfo& i) {
      i.min = lo;
      i.max = hi;
    });
  }
  KeyBuilder& at_least(double lo) {
    return edit([&](KeyInfo& i) { i.min = lo; });
  }
  KeyBuilder& at_most(double hi) {
    return edit([&](KeyInfo& i) { i.max = hi; });
  }
  KeyBuilder& positive() {
    return edit([&](KeyInfo& i) {
      i.min = 0.0;
      i.min_exclusive = true;
    });
  }
  KeyBuilder& non_negative() { return at_least(0.0); }
  // (0, hi]
  KeyBuilder& positive_up_to(double hi) {
    positive();
    return at_most(hi);
  }
  KeyBuilder& max_items(std::size_t count) {
    return edit([&](KeyInfo& i) { i.max_items = count; });
  }
  KeyBuilder& auto_allowed() {
    return edit([&](KeyInfo& i) { i.allows_auto = true; });
  }
  KeyBuilder& choices(std::vector<std::string> values) {
    return edit([&](KeyInfo& i) { i.choices = std::move(values); });
  }
  KeyBuilder& path() {
    return edit([&](KeyInfo& i) {
      i.type = i.type == ValueType::kStringList ? ValueType::kPathList : ValueType::kPath;
    });
  }
  KeyBuilder& output() {
    path();
    return edit([&](KeyInfo& i) { i.output = true; });
  }
  KeyBuilder& cli(std::string name) {
    return edit([&](KeyInfo& i) { i.cli_name = std::move(name); });
  }
  KeyBuilder& alias(std::string name) {
    return edit([&](KeyInfo& i) { i.cli_aliases.push_back(std::move(name)); });
  }
  KeyBuilder& repeatable() {
    return edit([&](KeyInfo& i) { i.repeatable = true; });
  }
  KeyBuilder& exclusive(std::string group) {
    return edit([&](KeyInfo& i) { i.exclusive_group = std::move(group); });
  }
  // The list's items may carry their own values of these keys: kPathEntries.
  KeyBuilder& entries(std::vector<KeyInfo> keys) {
    return edit([&](KeyInfo& i) {
      i.type = ValueType::kPathEntries;
      i.entry_keys = std::move(keys);
    });
  }
  KeyBuilder& implies(std::string other, Json::Value value) {
    return edit([&](KeyInfo& i) { i.implies.emplace_back(std::move(other), std::move(value)); });
  }

  operator Key<R>() const { return key_; }  // NOLINT: a builder reads as its key

 private:
  template <class F>
  KeyBuilder& edit(F&& f) {
    f(key_.info);
    return *this;
  }
  Key<R> key_;
};

// A key held in one field of the request.
template <class R, class T>
KeyBuilder<R> key(std::string name, T R::*field) {
  Key<R> k;
  k.info.name = std::move(name);
  k.info.type = key_detail::value_type<T>();
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    k.info.min = 0.0;
    k.info.max = static_cast<double>(std::numeric_limits<T>::max());
  }
  if constexpr (std::is_same_v<T, std::optional<double>>) k.info.allows_auto = true;
  k.set = [field](R& request, const Json::Value& value) {
    request.*field = key_detail::from_json<T>(value);
  };
  k.get = [field](const R& request) { return key_detail::to_json(request.*field); };
  k.info.default_value = key_detail::to_json(R{}.*field);
  return KeyBuilder<R>(std::move(k));
}

// A key whose setter and getter are written by hand (several fields, or a
// field of another shape). `default_value` is read from a default request.
template <class R>
KeyBuilder<R> custom_key(std::string name, ValueType type,
                         std::function<void(R&, const Json::Value&)> set,
                         std::function<Json::Value(const R&)> get) {
  Key<R> k;
  k.info.name = std::move(name);
  k.info.type = type;
  k.set = std::move(set);
  k.get = std::move(get);
  k.info.default_value = k.get(R{});
  return KeyBuilder<R>(std::move(k));
}

// The keys of a part of the request (e.g. the region-growing options held in
// `RegionGrowingRequest::estimation`), declared once for that part.
template <class R, class S>
Keys<R> mount(const Keys<S>& part, S R::*member) {
  Keys<R> keys;
  const R defaults{};
  for (const Key<S>& k : part) {
    Key<R> mounted;
    mounted.info = k.info;
    mounted.set = [member, set = k.set](R& r, const Json::Value& v) { set(r.*member, v); };
    mounted.get = [member, get = k.get](const R& r) { return get(r.*member); };
    mounted.info.default_value = mounted.get(defaults);
    keys.push_back(std::move(mounted));
  }
  return keys;
}

// The same keys without some of them (a part that a job only partly uses).
template <class R>
Keys<R> without(Keys<R> keys, const std::vector<std::string>& names) {
  Keys<R> kept;
  for (auto& k : keys) {
    bool drop = false;
    for (const auto& name : names) drop = drop || k.info.name == name;
    if (!drop) kept.push_back(std::move(k));
  }
  return kept;
}

template <class R>
Keys<R> join(std::initializer_list<Keys<R>> parts) {
  Keys<R> all;
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

// -- shared declarations: each key that several jobs take, declared once ------

// "viewpoints", "pattern" and "num_vp": one ViewpointChoice field; at most one
// of them per source.
template <class R>
Keys<R> viewpoint_keys(ViewpointChoice R::*field);

// The face-neutral info of keys, in declaration order.
template <class R>
std::vector<KeyInfo> key_infos(const Keys<R>& keys) {
  std::vector<KeyInfo> infos;
  for (const auto& k : keys) infos.push_back(k.info);
  return infos;
}

// -- checks --------------------------------------------------------------------

// "--point-radius" for "point_radius" (or the declared cli name).
std::string cli_spelling(const KeyInfo& info);
// The default for --help: "0.01", "wall,floor,ceiling"; "" when there is none.
std::string default_text(const KeyInfo& info);
// "a number > 0", "an integer 1..7", "one of uniform, fibonacci", ...
std::string describe_values(const KeyInfo& info);
// Checks type, range and choices; returns the value to store (CLI text already
// converted). Throws UsageError "<spelling> must be ..." .
void check_value(const KeyInfo& info, const Json::Value& value, const std::string& spelling);
// An item of a kPathEntries list: a bare path, or the entry's "path".
std::string entry_path(const Json::Value& item);
// A key's declaration as JSON (the server's `hello`, the docs).
Json::Value to_json(const KeyInfo& info);

// Every key's current value of `request` against its declaration: ranges hold
// whatever face (or C++ caller) filled the request. Throws KeyError.
template <class R>
void check_keys(const Keys<R>& keys, const R& request);

// The request's values of every key in force, for reports.
template <class R>
Json::Value parameters_json(const Keys<R>& keys, const R& request) {
  Json::Value parameters(Json::objectValue);
  for (const auto& k : keys) {
    Json::Value value = k.get(request);
    if (!value.isNull()) parameters[k.info.name] = std::move(value);
  }
  return parameters;
}

}  // namespace occlusion

#include "occlusion/app/key_impl.hpp"
