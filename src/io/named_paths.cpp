#include "occlusion/io/named_paths.hpp"

#include <filesystem>
#include <utility>

namespace occlusion {
namespace {

thread_local NamedPathRule rule_in_force;

}  // namespace

NamedPathScope::NamedPathScope(NamedPathRule rule) : replaced_(std::move(rule_in_force)) {
  rule_in_force = std::move(rule);
}

NamedPathScope::~NamedPathScope() {
  rule_in_force = std::move(replaced_);
}

std::string resolve_named_path(const std::string& file, const std::string& named) {
  if (rule_in_force) return rule_in_force(file, named);
  const std::filesystem::path given(named);
  if (given.is_absolute()) return given.string();
  return (std::filesystem::path(file).parent_path() / given).string();
}

}  // namespace occlusion
