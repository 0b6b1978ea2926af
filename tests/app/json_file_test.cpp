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

TEST_F(JsonFile, ReadsCommentsAndRefusesDuplicateKeys) {
  const std::string good = write("good.json", "// a comment\n{\"a\": [1, 2]}\n");
  EXPECT_EQ(read_json_file(good, "config file")["a"][1].asInt(), 2);
  const std::string twice = write("twice.json", "{\"a\": 1, \"a\": 2}");
  EXPECT_NE(usage_error([&] { read_json_file(twice, "config file"); }).find("not valid JSON"),
            std::string::npos);
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
