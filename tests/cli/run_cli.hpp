#pragma once
// Runs the built `occlusion` binary as a user would, capturing its output.

#include <json/value.h>

#include <string>

namespace occlusion::testing {

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// `arguments` is appended to the binary's path as shell words.
CliRun run_cli(const std::string& arguments);

// The one JSON object of a --json run; a parse failure fails the test.
Json::Value parse_json(const std::string& text);
// run_cli(args + " --json -q"), expecting exit code 0, parsed.
Json::Value run_json(const std::string& arguments);

// A fresh, empty directory under the system temp dir, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  void write(const std::string& name, const std::string& text) const;

 private:
  std::string path_;
};

std::string read_text(const std::string& path);

}  // namespace occlusion::testing
