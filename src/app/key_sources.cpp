#include "occlusion/app/key_sources.hpp"

#include <charconv>
#include <cmath>
#include <map>

#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_file.hpp"

namespace occlusion {

namespace {

const KeyInfo* find_info(const std::vector<KeyInfo>& infos, const std::string& name) {
  for (const auto& info : infos) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

bool is_list(ValueType type) {
  return type == ValueType::kStringList || type == ValueType::kPathList ||
         type == ValueType::kIntegerList || type == ValueType::kNumberList ||
         type == ValueType::kPointList || type == ValueType::kViewpointSets ||
         type == ValueType::kPathEntries;
}

std::vector<std::string> split_list(const std::string& text, char separator = ',') {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(separator, start);
    if (end == std::string::npos) end = text.size();
    if (end > start) items.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return items;
}

Json::Value parse_number(const std::string& option, const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw KeyError("", "expects a number, got '" + text + "'", option);
  }
  return value;
}

Json::Value parse_integer(const std::string& option, const std::string& text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) {
    throw KeyError("", "expects a non-negative integer, got '" + text + "'", option);
  }
  return Json::UInt64(value);
}

std::optional<bool> bool_word(const std::string& text) {
  if (text == "true" || text == "1" || text == "on" || text == "yes") return true;
  if (text == "false" || text == "0" || text == "off" || text == "no") return false;
  return std::nullopt;
}

Json::Value parse_point(const std::string& option, const std::string& text) {
  const std::vector<std::string> parts = split_list(text);
  if (parts.size() != 3 || std::count(text.begin(), text.end(), ',') != 2) {
    throw KeyError("", "expects X,Y,Z, got '" + text + "'", option);
  }
  Json::Value point(Json::arrayValue);
  for (const auto& part : parts) point.append(parse_number(option, part));
  return point;
}

// One item (a repeatable list's) or the whole value, from command-line text.
Json::Value from_text(const KeyInfo& info, const std::string& option, const std::string& text) {
  if (info.allows_auto && text == "auto") return "auto";
  switch (info.type) {
    case ValueType::kNumber:
      return parse_number(option, text);
    case ValueType::kInteger:
      return parse_integer(option, text);
    case ValueType::kBool: {
      const auto value = bool_word(text);
      if (!value) throw KeyError("", "expects true or false, got '" + text + "'", option);
      return *value;
    }
    case ValueType::kString:
    case ValueType::kPath:
      return text;
    case ValueType::kStringList:
    case ValueType::kPathList: {
      if (info.repeatable) return text;
      Json::Value list(Json::arrayValue);
      for (const auto& item : split_list(text)) list.append(item);
      return list;
    }
    case ValueType::kIntegerList: {
      if (info.repeatable) return parse_integer(option, text);
      Json::Value list(Json::arrayValue);
      for (const auto& item : split_list(text)) list.append(parse_integer(option, item));
      return list;
    }
    case ValueType::kNumberList: {
      Json::Value list(Json::arrayValue);
      for (const auto& item : split_list(text)) list.append(parse_number(option, item));
      return list;
    }
    case ValueType::kPointList:
      return parse_point(option, text);
    case ValueType::kViewpointSets:
      return parse_json_text(text, option);
    case ValueType::kPathEntries:
      // An entry with values of its own is its JSON object; anything else a path.
      if (info.repeatable) return text.rfind('{', 0) == 0 ? parse_json_text(text, option) : text;
      return parse_json_text(text, option);
  }
  throw UsageError(option + ": a value of an unknown type");
}

std::string group_spellings(const KeySource& source, const std::vector<KeyInfo>& infos,
                            const std::string& group) {
  std::vector<std::string> names;
  for (const auto& info : infos) {
    if (info.exclusive_group == group) {
      names.push_back(face_spelling(source.face, info, source.section));
    }
  }
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  return text;
}

// An entry's path, and its values of path keys, as the face resolves paths.
void resolve_entry(const KeyInfo& info, Json::Value& item, const PathResolver& resolve) {
  if (item.isString()) {
    item = resolve(item.asString(), info.output);
    return;
  }
  item["path"] = resolve(item["path"].asString(), info.output);
  for (const auto& entry : info.entry_keys) {
    if (entry.type == ValueType::kPath && item.isMember(entry.name) &&
        !item[entry.name].asString().empty()) {
      item[entry.name] = resolve(item[entry.name].asString(), entry.output);
    }
  }
}

}  // namespace

const KeyValue* KeySource::find(const std::string& key) const {
  const KeyValue* found = nullptr;
  for (const auto& value : values) {
    if (value.key == key) found = &value;
  }
  return found;
}

std::string face_spelling(Face face, const KeyInfo& info, const std::string& section) {
  switch (face) {
    case Face::kCli:
      return cli_spelling(info);
    case Face::kConfig:
      return "'occlusion." + section + "." + info.name + "'";
    case Face::kServer:
    case Face::kPython:
      break;
  }
  return "'" + info.name + "'";
}

KeySource source_from_json(const Json::Value& object, const std::vector<KeyInfo>& infos, Face face,
                           const std::string& prefix, const std::string& section,
                           const PathResolver& resolve) {
  KeySource source;
  source.face = face;
  source.prefix = prefix;
  source.section = section;
  if (!object.isObject()) {
    throw UsageError(prefix + (face == Face::kConfig ? "'occlusion." + section + "'" : "params") +
                     " must be an object");
  }
  for (const auto& name : object.getMemberNames()) {
    const KeyInfo* info = find_info(infos, name);
    KeyInfo unknown;
    unknown.name = name;
    const std::string spelling = face_spelling(face, info ? *info : unknown, section);
    if (info == nullptr) throw UsageError(prefix + "unknown key " + spelling);
    Json::Value value = object[name];
    check_value(*info, value, prefix + spelling);
    if (resolve && info->type == ValueType::kPath && !value.asString().empty()) {
      value = resolve(value.asString(), info->output);
    }
    if (resolve && info->type == ValueType::kPathList) {
      for (auto& item : value) item = resolve(item.asString(), info->output);
    }
    if (resolve && info->type == ValueType::kPathEntries) {
      for (auto& item : value) resolve_entry(*info, item, resolve);
    }
    source.values.push_back({name, value, spelling});
  }
  return source;
}

KeySource source_from_arguments(const std::vector<std::string>& args,
                                const std::vector<KeyInfo>& infos, const std::string& command,
                                const std::string& positional_key) {
  std::map<std::string, const KeyInfo*> options;
  for (const auto& info : infos) {
    options[cli_spelling(info)] = &info;
    for (const auto& alias : info.cli_aliases) options[alias] = &info;
  }
  KeySource source;
  source.face = Face::kCli;
  std::map<std::string, std::size_t> index;  // key -> position in source.values
  const auto store = [&](const KeyInfo& info, const std::string& spelling, Json::Value value) {
    const auto at = index.find(info.name);
    if (info.repeatable || (info.name == positional_key && is_list(info.type))) {
      if (at == index.end()) {
        index[info.name] = source.values.size();
        source.values.push_back({info.name, Json::Value(Json::arrayValue), spelling});
      }
      source.values[index[info.name]].value.append(value);
      return;
    }
    if (at != index.end()) {
      source.values[at->second].value = value;  // the last one given wins
      return;
    }
    index[info.name] = source.values.size();
    source.values.push_back({info.name, value, spelling});
  };

  const KeyInfo* positional = find_info(infos, positional_key);
  bool positional_given = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.size() < 2 || arg[0] != '-') {
      if (positional == nullptr || (positional_given && !is_list(positional->type))) {
        throw UsageError("unexpected argument '" + arg + "': " + command +
                         (positional == nullptr ? " takes no input argument" : " takes one input"));
      }
      positional_given = true;
      store(*positional, face_spelling(Face::kCli, *positional, ""), arg);
      continue;
    }
    const std::size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    const auto option = options.find(name);
    if (option == options.end()) {
      throw UsageError("unknown option '" + name + "' for " + command + " (see occlusion " +
                       command + " --help)");
    }
    const KeyInfo& info = *option->second;
    std::string text;
    if (equals != std::string::npos) {
      text = arg.substr(equals + 1);
    } else if (info.type == ValueType::kBool) {
      const bool word_follows = i + 1 < args.size() && bool_word(args[i + 1]).has_value();
      text = word_follows ? args[++i] : "true";
    } else {
      if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
      text = args[++i];
    }
    store(info, name, from_text(info, name, text));
  }
  for (const auto& value : source.values) {
    check_value(*find_info(infos, value.key), value.value, value.spelling);
  }
  return source;
}

std::vector<KeyValue> expanded(const KeySource& source, const std::vector<KeyInfo>& infos) {
  std::map<std::string, std::string> group_member;
  for (const auto& value : source.values) {
    const KeyInfo* info = find_info(infos, value.key);
    if (info == nullptr || info->exclusive_group.empty()) continue;
    const auto [at, fresh] = group_member.emplace(info->exclusive_group, value.key);
    if (!fresh && at->second != value.key) {
      throw UsageError(source.prefix + "give one of " +
                       group_spellings(source, infos, info->exclusive_group));
    }
  }
  std::vector<KeyValue> values = source.values;
  for (const auto& value : source.values) {
    const KeyInfo* info = find_info(infos, value.key);
    if (info == nullptr) continue;
    for (const auto& [other, implied] : info->implies) {
      if (source.find(other) == nullptr) values.push_back({other, implied, value.spelling});
    }
  }
  return values;
}

UsageError respelled(const KeyError& error, const std::vector<KeySource>& sources,
                     const std::vector<KeyInfo>& infos) {
  for (auto source = sources.rbegin(); source != sources.rend(); ++source) {
    if (const KeyValue* value = source->find(error.key)) {
      return UsageError(source->prefix + value->spelling + " " + error.problem);
    }
  }
  const KeyInfo* info = find_info(infos, error.key);
  if (info == nullptr || sources.empty()) return UsageError(error.what());
  const KeySource& last = sources.back();
  return UsageError(last.prefix + face_spelling(last.face, *info, last.section) + " " +
                    error.problem);
}

}  // namespace occlusion
