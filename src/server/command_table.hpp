#pragma once
// Every command of the protocol, by name. A command either runs on the
// network thread (quick ones), on a worker (loads and jobs), or is handled by
// the session itself (cancel, upload). Adding a job is one entry in
// job_commands.cpp.

#include <functional>
#include <string>
#include <vector>

#include <json/value.h>

#include "command_context.hpp"

namespace occlusion::server {

enum class Where { kNetwork, kWorker, kSession };

struct Command {
  std::string name;
  Where where = Where::kWorker;
  // Returns the reply's "result". Empty: part of the protocol, not in this
  // build yet (answered with not_available).
  std::function<Json::Value(CommandContext&)> run;
  // Short work a client waits on to go on (loads, uploads, the live
  // station): not held back behind the client's own jobs, and it may start
  // on the pool's reserve while every worker is busy.
  bool waited_on = false;

  bool available() const { return where == Where::kSession || static_cast<bool>(run); }
};

const std::vector<Command>& command_table();
const Command* find_command(const std::string& name);

// The command groups the table is made of.
std::vector<Command> file_commands();          // ping, list_files, save_polygon, read_polygons
std::vector<Command> load_commands();          // load
std::vector<Command> job_commands();           // mesh_occlusion, cloud_occlusion, ...
std::vector<Command> live_station_commands();  // station_view

}  // namespace occlusion::server
