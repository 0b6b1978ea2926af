#pragma once
// What makes an output set's commit (io/atomic_file.hpp) survive a SIGKILL or
// a crash: the set's renames are announced by a manifest, and a later sweep of
// the folder finishes them. A process killed
//   - while writing its temporaries (no manifest yet) leaves the previous
//     outputs as they were, and the sweep removes its temporaries;
//   - between its renames (the manifest is there) leaves old and new outputs
//     mixed until the sweep renames the remaining temporaries: the new set,
//     whole;
//   - after its renames, before removing its manifest: the sweep removes it.
// Names: temporaries `.tmp-PID-N-NAME`, manifests `.commit-PID-N`, where PID is
// the writing process. Only files of processes that no longer run are swept.

#include <string>
#include <utility>
#include <vector>

namespace occlusion {

// The manifest of a set whose first target is in `dir`, for process `pid`.
std::string commit_manifest_path(const std::string& dir, long pid, unsigned long serial);

// Writes the manifest (atomically) naming each (temporary, target) pair, so a
// sweep can finish the renames. OutputError if it cannot be written.
void write_commit_manifest(const std::string& manifest,
                           const std::vector<std::pair<std::string, std::string>>& files);

struct RecoveredOutputs {
  std::size_t completed_sets = 0;       // dead processes' manifests finished and removed
  std::size_t removed_temporaries = 0;  // dead processes' temporaries removed
};

// Sweeps `dir` of what dead processes left: finishes the renames of each set
// whose manifest is there (a target written since the manifest is kept, the
// older temporary dropped), then removes their other temporaries. Quiet and
// best effort: a file that cannot be touched is left for the next sweep.
RecoveredOutputs recover_outputs(const std::string& dir);

}  // namespace occlusion
