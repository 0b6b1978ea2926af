#pragma once
// A command's options: each name (and alias) maps to what it sets. Parsing
// walks the arguments once; anything that is not an option is positional.

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace occlusion::cli {

class OptionTable {
 public:
  explicit OptionTable(std::string command) : command_(std::move(command)) {}

  // An option without a value, e.g. --json.
  void flag(const std::vector<std::string>& names, std::function<void()> on);
  // An option with one value, e.g. --seed 3; `on` receives (option name, value).
  void value(const std::vector<std::string>& names,
             std::function<void(const std::string&, const std::string&)> on);

  // Throws UsageError for an unknown option or a missing value.
  void parse(const std::vector<std::string>& args,
             const std::function<void(const std::string&)>& positional) const;

 private:
  struct Entry {
    bool takes_value = false;
    std::function<void()> on_flag;
    std::function<void(const std::string&, const std::string&)> on_value;
  };
  std::string command_;
  std::map<std::string, Entry> entries_;
};

}  // namespace occlusion::cli
