#include "command_table.hpp"

namespace occlusion::server {

const std::vector<Command>& command_table() {
  static const std::vector<Command> kTable = [] {
    std::vector<Command> table;
    for (auto group : {file_commands(), load_commands(), job_commands(), live_station_commands()}) {
      for (auto& command : group) table.push_back(std::move(command));
    }
    table.push_back(Command{"upload", Where::kSession, {}, true});
    table.push_back(Command{"cancel", Where::kSession, {}});
    return table;
  }();
  return kTable;
}

const Command* find_command(const std::string& name) {
  for (const auto& command : command_table()) {
    if (command.name == name) return &command;
  }
  return nullptr;
}

}  // namespace occlusion::server
