#pragma once
// Outputs appear whole or not at all: a reader (the viewer, a script, a second
// run) never sees a half-written file, and a failed run leaves the previous
// output in place.

#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace occlusion {

// Calls `write` on a binary stream to a temporary file in the same directory as
// `path` (so the rename cannot cross file systems), checks that every byte
// reached the file, then renames it onto `path`, replacing any existing file.
// On failure the temporary file is removed and OutputError names `path`; an
// exception thrown by `write` removes it too and propagates unchanged.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

// A job's outputs, which appear together or not at all: each writer writes to
// the temporary name `add` gives (beside its target), and `commit` renames
// them all onto their targets once every one is written. An OutputSet
// destroyed without commit (a writer threw, the run was cancelled or
// interrupted) removes its temporaries and leaves the previous outputs as they
// were. A process killed outright (SIGKILL) cannot clean up: a manifest
// written before the renames lets a later sweep finish them, and remove the
// temporaries (io/output_recovery.hpp); commit sweeps its folders first.
//
//   OutputSet outputs;
//   write_mesh_ply(outputs.add(ply_path), ...);
//   write_json_report(outputs.add(json_path), ...);
//   outputs.commit();
class OutputSet {
 public:
  OutputSet() = default;
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // The temporary name to write `target` to. OutputError for a path without a
  // file name or a target named twice.
  std::string add(const std::string& target);
  // Renames every temporary onto its target. OutputError, with every
  // temporary removed and no target touched, if one of them was not written.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> files_;  // temporary, target
  bool committed_ = false;
};

// Creates `dir` and its missing parents. OutputError if it exists as something
// other than a directory or cannot be created. An empty string is the current
// directory and is left alone.
void ensure_directory(const std::string& dir);

}  // namespace occlusion
