#include "option_table.hpp"

#include "occlusion/app/errors.hpp"

namespace occlusion::cli {

void OptionTable::flag(const std::vector<std::string>& names, std::function<void()> on) {
  for (const auto& name : names) entries_[name] = Entry{false, on, {}};
}

void OptionTable::value(const std::vector<std::string>& names,
                        std::function<void(const std::string&, const std::string&)> on) {
  for (const auto& name : names) entries_[name] = Entry{true, {}, on};
}

void OptionTable::parse(const std::vector<std::string>& args,
                        const std::function<void(const std::string&)>& positional) const {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool looks_like_option = arg.size() > 1 && arg[0] == '-';
    if (!looks_like_option) {
      positional(arg);
      continue;
    }
    const auto entry = entries_.find(arg);
    if (entry == entries_.end()) {
      throw UsageError("unknown option '" + arg + "' for " + command_ + " (see occlusion " +
                       command_ + " --help)");
    }
    if (!entry->second.takes_value) {
      entry->second.on_flag();
      continue;
    }
    if (i + 1 >= args.size()) throw UsageError(arg + " needs a value");
    entry->second.on_value(arg, args[++i]);
  }
}

}  // namespace occlusion::cli
