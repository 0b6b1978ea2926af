// The command line the server offers beside a result (`reproduce`) is read by
// the CLI's own parser as the keys it was made from: the same values, every
// digit of a viewpoint kept, paths with spaces and quotes intact.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "occlusion/app/command_line.hpp"
#include "occlusion/app/json_file.hpp"
#include "occlusion/app/key_sources.hpp"

namespace occlusion {
namespace {

// The words a POSIX shell makes of `command` (plain words, '...' quotes and
// \' between them, which is all cli_command writes).
std::vector<std::string> shell_words(const std::string& command) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false, quoted = false, escaped = false;
  for (const char c : command) {
    if (escaped) {
      word += c;
      escaped = false;
    } else if (!quoted && c == '\\') {
      escaped = in_word = true;
    } else if (quoted) {
      if (c == '\'') {
        quoted = false;
      } else {
        word += c;
      }
    } else if (c == '\'') {
      quoted = in_word = true;
    } else if (c == ' ') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

Json::Value parsed(const std::string& text) {
  return parse_json_text(text, "test");
}

// Equal values, numbers by value (the parser reads 41 as 41.0).
bool same(const Json::Value& a, const Json::Value& b) {
  if (a.isNumeric() && b.isNumeric() && !a.isBool() && !b.isBool()) {
    return a.asDouble() == b.asDouble();
  }
  if (a.isArray() && b.isArray()) {
    if (a.size() != b.size()) return false;
    for (Json::ArrayIndex i = 0; i < a.size(); ++i) {
      if (!same(a[i], b[i])) return false;
    }
    return true;
  }
  return a == b;
}

TEST(CommandLine, TheCliReadsBackTheKeysItWasMadeFrom) {
  const JobInfo& job = *find_job("cloud_occlusion");
  const Json::Value params = parsed(R"({
    "path": "scans/it's a room.pcd", "num_rays_per_vp": 20000, "seed": 0,
    "viewpoints": [[1.0000000000000002, -2.5, 0.1], [3, 4, 5]],
    "escape_directions": true, "sampling": "fibonacci", "field_of_view": [57.5, 41],
    "scans": ["Scan 01", "Scan 02"]})");
  const std::string command = cli_command(job, params);
  std::vector<std::string> words = shell_words(command);
  ASSERT_GE(words.size(), 3u) << command;
  EXPECT_EQ(words[0], "occlusion");
  EXPECT_EQ(words[1], "-poc");
  words.erase(words.begin(), words.begin() + 2);
  const KeySource source = source_from_arguments(words, job.keys, "-poc", job.positional);
  EXPECT_EQ(source.values.size(), params.size()) << command;
  for (const std::string& key : params.getMemberNames()) {
    const KeyValue* value = source.find(key);
    ASSERT_NE(value, nullptr) << key << " in " << command;
    // The positional path comes back as the list of inputs it may be.
    const Json::Value& read =
        value->value.isArray() && params[key].isString() ? value->value[0] : value->value;
    EXPECT_TRUE(same(read, params[key])) << key << ": " << read << " in " << command;
  }
}

TEST(CommandLine, PythonCallTakesThePathFirstAndTheRestAsKeywords) {
  const JobInfo& job = *find_job("scan");
  const std::string call =
      python_call(job, parsed(R"({"path": "room.pcd", "pattern": 4, "escape": null})"));
  EXPECT_EQ(call, "occlusion.scan(\"room.pcd\", pattern=4)");
}

}  // namespace
}  // namespace occlusion
