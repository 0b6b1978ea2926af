// JSON files the user gives (config, class mapping) fail as usage errors,
// whatever is wrong with them: deep nesting, a FIFO, a directory (issue 13).

#include "occlusion/app/json_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"

namespace occlusion {
namespace {

class JsonFile : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("occlusion_json_file_" + std::to_string(::getpid()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (directory_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::filesystem::path directory_;
};

std::string usage_error(const std::function<void()>& body) {
  try {
    body();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no UsageError)";
}

TEST_F(JsonFile, ReadsJsonAndRefusesWhatJsonDoesNotAllow) {
  const std::string good = write("good.json", "{\"a\": [1, 2]}\n");
  EXPECT_EQ(read_json_file(good, "config file")["a"][1].asInt(), 2);
  // Each would be read with something ignored or cut (issue 44): the second
  // object, the commented-out key, a path short of its NUL.
  const std::vector<std::string> refused = {
      "{\"a\": 1, \"a\": 2}",
      "{\"a\": 1}\n{\"a\": 2}\n",
      "{\"a\": 1} x",
      "// a comment\n{\"a\": 1}",
      "{\"a\": 1 /* \"b\": 2 */}",
      "{\"a\": [1, 2,]}",
      "{\"a\": 1,}",
      "{\"out\": \"results\\u0000/elsewhere\"}",
      "{\"a\\u0000b\": 1}",
  };
  for (const std::string& text : refused) {
    SCOPED_TRACE(text);
    const std::string path = write("refused.json", text);
    const std::string message = usage_error([&] { read_json_file(path, "config file"); });
    EXPECT_NE(message.find("refused.json: not valid JSON"), std::string::npos) << message;
  }
  const std::string twice = write("two_objects.json", "{}\n{\"occlusion\": 1}\n");
  const std::string message = usage_error([&] { load_config(twice); });
  EXPECT_NE(message.find("two_objects.json: not valid JSON"), std::string::npos) << message;
}

TEST_F(JsonFile, DeepNestingIsAUsageErrorNotAnInternalOne) {
  const std::string deep = write("deep.json", std::string(100000, '[') + std::string(100000, ']'));
  const std::string message = usage_error([&] { load_config(deep); });
  EXPECT_NE(message.find("deep.json: not valid JSON"), std::string::npos) << message;
}

TEST_F(JsonFile, SpecialFilesAreUsageErrors) {
  const std::string fifo = (directory_ / "fifo.json").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string message = usage_error([&] { load_config(fifo); });
  EXPECT_NE(message.find("cannot read config file: is a FIFO"), std::string::npos) << message;
  std::filesystem::create_directories(directory_ / "folder.json");
  message = usage_error([&] { load_config((directory_ / "folder.json").string()); });
  EXPECT_NE(message.find("is a directory"), std::string::npos) << message;
  message = usage_error([&] { read_json_file("/dev/zero", "class mapping file"); });
  EXPECT_NE(message.find("cannot read class mapping file: is a character device"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace occlusion
