#include "occlusion/analysis/class_mapping.hpp"

#include <stdexcept>

#include "occlusion/core/nyu40_classes.hpp"

namespace occlusion {

namespace {

[[noreturn]] void fail(const std::string& message) {
  throw std::invalid_argument("class mapping: " + message);
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

}  // namespace

ClassMapping::ClassMapping(std::map<std::string, std::int32_t> ids,
                           std::map<std::int32_t, std::string> names, std::set<std::string> ignored,
                           std::int32_t ignore_id)
    : ids_(std::move(ids)),
      names_(std::move(names)),
      ignored_(std::move(ignored)),
      ignore_id_(ignore_id) {
  std::map<std::int32_t, std::vector<std::string>> classes_of_id;
  for (const auto& [name, id] : ids_) {
    if (name.empty()) fail("a ground-truth class name is empty");
    if (id < 0) fail("class '" + name + "' has negative id " + std::to_string(id));
    if (id == ignore_id_) {
      fail("class '" + name + "' has the ignore id " + std::to_string(id) +
           " (list it in ignored_classes instead)");
    }
    if (ignored_.count(name) == 0) classes_of_id[id].push_back(name);
  }
  for (const auto& [id, name] : names_) {
    if (name.empty()) fail("evaluation id " + std::to_string(id) + " has an empty name");
    bool used = false;
    for (const auto& entry : ids_) used = used || entry.second == id;
    if (!used) fail("a name is given for id " + std::to_string(id) + ", which no class maps to");
  }
  for (const auto& [id, members] : classes_of_id) {
    const auto name = names_.find(id);
    std::string joined_name;
    for (const auto& member : members) joined_name += (joined_name.empty() ? "" : "+") + member;
    classes_.push_back({id, name != names_.end() ? name->second : joined_name});
  }
  if (classes_.empty()) fail("no class is left to evaluate");
}

ClassMapping ClassMapping::seed_table() {
  return ClassMapping({{"wall", 0},
                       {"floor", 1},
                       {"ceiling", 1},
                       {"chair", 4},
                       {"sofa", 5},
                       {"table", 6},
                       {"door", 7},
                       {"window", 8},
                       {"bookcase", 9},
                       {"beam", 20},
                       {"board", 21},
                       {"clutter", 25},
                       {"column", 26}},
                      {{1, "floor+ceiling"}});
}

ClassMapping ClassMapping::scannet20() {
  const std::vector<std::string>& nyu40 = nyu40_class_names();
  std::map<std::string, std::int32_t> ids;
  std::map<std::int32_t, std::string> names;
  for (const ScanNetBenchmarkClass& c : scannet20_classes()) {
    ids[nyu40.at(static_cast<std::size_t>(c.nyu40_id))] = c.nyu40_id;
    names[c.nyu40_id] = c.name;
  }
  std::set<std::string> ignored;
  for (const std::string& name : nyu40) {
    if (ids.count(name) == 0) ignored.insert(name);
  }
  return ClassMapping(ids, names, ignored);
}

std::optional<ClassMapping> ClassMapping::builtin(const std::string& name) {
  if (name == "table3.1") return seed_table();
  if (name == "scannet20") return scannet20();
  return std::nullopt;
}

const std::vector<std::string>& ClassMapping::builtin_names() {
  static const std::vector<std::string> names = {"table3.1", "scannet20"};
  return names;
}

ClassMapping ClassMapping::with_ignored(const std::vector<std::string>& classes) const {
  std::set<std::string> ignored = ignored_;
  ignored.insert(classes.begin(), classes.end());
  return ClassMapping(ids_, names_, ignored, ignore_id_);
}

std::optional<std::int32_t> ClassMapping::find(const std::string& class_name) const {
  if (ignored_.count(class_name) > 0) return ignore_id_;
  const auto it = ids_.find(class_name);
  if (it == ids_.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> ClassMapping::unmapped_classes(
    const std::vector<std::int32_t>& labels, const std::vector<std::string>& class_names) const {
  std::vector<bool> used(class_names.size(), false);
  for (const auto label : labels) {
    if (label >= 0 && static_cast<std::size_t>(label) < used.size()) {
      used[static_cast<std::size_t>(label)] = true;
    }
  }
  std::set<std::string> unmapped;
  for (std::size_t i = 0; i < class_names.size(); ++i) {
    if (used[i] && !find(class_names[i])) unmapped.insert(class_names[i]);
  }
  return {unmapped.begin(), unmapped.end()};
}

std::vector<std::int32_t> ClassMapping::map_labels(
    const std::vector<std::int32_t>& labels, const std::vector<std::string>& class_names) const {
  const std::vector<std::string> unmapped = unmapped_classes(labels, class_names);
  if (!unmapped.empty()) fail("classes not in the mapping: " + joined(unmapped));
  std::vector<std::int32_t> table;
  table.reserve(class_names.size());
  for (const auto& name : class_names) table.push_back(find(name).value_or(ignore_id_));
  std::vector<std::int32_t> mapped;
  mapped.reserve(labels.size());
  for (const auto label : labels) {
    if (label < 0) {
      mapped.push_back(ignore_id_);
    } else if (static_cast<std::size_t>(label) < table.size()) {
      mapped.push_back(table[static_cast<std::size_t>(label)]);
    } else {
      fail("label " + std::to_string(label) + " has no class name");
    }
  }
  return mapped;
}

}  // namespace occlusion
