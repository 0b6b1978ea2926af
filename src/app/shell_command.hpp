#pragma once
// Running a command the user wrote (the study's --segmenter), internal to app/.

#include <string>

#include "occlusion/analysis/progress.hpp"

namespace occlusion::job {

// `text` as one shell word: 'it'\''s' for it's.
std::string shell_quote(const std::string& text);

// Runs `command` with /bin/sh -c in its own process group, stdin from
// /dev/null and its stdout on our stderr (our stdout carries --json's one
// object). Returns the exit status; a command killed by signal s returns
// 128 + s, as the shell reports it. On cancel the whole group is killed and
// Cancelled thrown. std::runtime_error when no process can be started.
int run_shell_command(const std::string& command, const Progress& progress);

}  // namespace occlusion::job
