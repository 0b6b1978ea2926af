#pragma once
// Outputs appear whole or not at all: a reader (the viewer, a script, a second
// run) never sees a half-written file, and a failed run leaves the previous
// output in place.

#include <functional>
#include <ostream>
#include <string>

namespace occlusion {

// Calls `write` on a binary stream to a temporary file in the same directory as
// `path` (so the rename cannot cross file systems), checks that every byte
// reached the file, then renames it onto `path`, replacing any existing file.
// On failure the temporary file is removed and OutputError names `path`; an
// exception thrown by `write` removes it too and propagates unchanged.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

// Creates `dir` and its missing parents. OutputError if it exists as something
// other than a directory or cannot be created. An empty string is the current
// directory and is left alone.
void ensure_directory(const std::string& dir);

}  // namespace occlusion
