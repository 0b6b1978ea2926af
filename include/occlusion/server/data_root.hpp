#pragma once
// The data directory (`serve --data`): every path a client names is relative
// to it, and none may lead out of it, neither by `..`, nor by being absolute,
// nor through a symbolic link. Replies name files relative to it too, so the
// server's own file-system layout never reaches the browser.

#include <json/value.h>

#include <filesystem>
#include <string>

namespace occlusion::server {

class DataRoot {
 public:
  // Throws std::invalid_argument unless `directory` is an existing directory.
  explicit DataRoot(const std::string& directory);

  // The canonical data directory.
  const std::filesystem::path& path() const { return root_; }

  // The canonical file for a client's path ("" is the data directory itself).
  // Throws ProtocolError "path_outside_data" for an absolute path or one whose
  // canonical form (symbolic links resolved) is not inside the data directory,
  // and "not_found" when `must_exist` and nothing is there. `must_exist` means
  // an input: a folder is then also refused when a symbolic link anywhere in
  // it (four levels down, as deep as an S3DIS Area's files) leads out.
  std::filesystem::path resolve(const std::string& relative, bool must_exist) const;

  // A path that the file `file` (of the data directory, as resolve gives it)
  // names inside it, such as a depth frame's image: by resolve's rule, from
  // that file's folder, so an absolute path is refused as a client's is.
  // Throws ProtocolError naming `file`. Whether it exists is for its reader to say.
  std::filesystem::path resolve_named(const std::string& file, const std::string& named) const;

  // `path` relative to the data directory with '/' separators, "" for the
  // directory itself; paths outside are returned unchanged.
  std::string relative(const std::string& path) const;

  // `text` with every path inside the data directory that it names, as a
  // whole or within a sentence (where it starts the text or follows a space,
  // a quote or a bracket), in its relative form: a warning naming a depth
  // frame's image, which resolve_named made absolute, names it as the client does.
  std::string relative_in(const std::string& text) const;

  // Rewrites, in place, every string of `json` that names a file inside the
  // data directory into its relative form (relative_in).
  void relativise(Json::Value& json) const;

 private:
  // Throws ProtocolError for a link under `dir` leading outside; `seen` counts entries.
  void check_nested(const std::filesystem::path& dir, const std::string& relative, int depth,
                    std::size_t& seen) const;

  std::filesystem::path root_;
  std::string prefix_;  // root_ + '/'
};

}  // namespace occlusion::server
