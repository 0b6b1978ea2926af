#include "run_cli.hpp"

#include <gtest/gtest.h>
#include <json/reader.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace occlusion::testing {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = (std::filesystem::temp_directory_path() /
           ("occlusion-cli-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++)))
              .string();
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void TempDir::write(const std::string& name, const std::string& text) const {
  std::ofstream(file(name), std::ios::binary) << text;
}

Json::Value parse_json(const std::string& text) {
  Json::Value value;
  Json::CharReaderBuilder builder;
  std::string errors;
  std::istringstream in(text);
  EXPECT_TRUE(Json::parseFromStream(builder, in, &value, &errors)) << errors << "\n" << text;
  return value;
}

Json::Value run_json(const std::string& arguments) {
  const CliRun run = run_cli(arguments + " --json -q");
  EXPECT_EQ(run.exit_code, 0) << arguments << "\n" << run.err;
  return parse_json(run.out);
}

CliRun run_cli(const std::string& arguments) {
  const TempDir capture;
  const std::string command = std::string("'") + OCCLUSION_CLI_PATH + "' " + arguments + " >'" +
                              capture.file("out") + "' 2>'" + capture.file("err") + "' </dev/null";
  const int status = std::system(command.c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = read_text(capture.file("out"));
  run.err = read_text(capture.file("err"));
  return run;
}

}  // namespace occlusion::testing
