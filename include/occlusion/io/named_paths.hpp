#pragma once
// Paths that a file names: a depth frame's descriptor names its depth and
// colour images, relative to its own folder or absolute. Which of them may be
// opened is the rule of whoever asked for the read, not the file's. The
// command line and Python open what their user's files name, as they open
// any path their user gives. The server opens files of its data directory
// only: it puts its rule in force around every request it runs, so that no
// file there, nor an upload, can name one outside.
//
// The rule is the calling thread's: readers open the paths a file names on
// the thread that asked for the read.

#include <functional>
#include <string>

namespace occlusion {

// The path to open for `named`, which the file `file` names; throws to refuse it.
using NamedPathRule = std::function<std::string(const std::string& file, const std::string& named)>;

// Puts `rule` in force for this thread's reads while it lives; the rule it
// replaced comes back after it.
class NamedPathScope {
 public:
  explicit NamedPathScope(NamedPathRule rule);
  ~NamedPathScope();
  NamedPathScope(const NamedPathScope&) = delete;
  NamedPathScope& operator=(const NamedPathScope&) = delete;

 private:
  NamedPathRule replaced_;
};

// `named` as the rule in force resolves it; without one, as the file names
// it: relative to `file`'s folder, or absolute.
std::string resolve_named_path(const std::string& file, const std::string& named);

}  // namespace occlusion
