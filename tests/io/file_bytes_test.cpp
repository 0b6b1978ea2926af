// Every reader opens its file through read_file_bytes, which reads regular
// files only: a FIFO must not block, a device must not be read until memory
// runs out, a directory is named as one (issue 13).

#include "occlusion/io/file_bytes.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/label_file.hpp"
#include "occlusion/io/obj_reader.hpp"
#include "occlusion/io/polygon_file.hpp"

namespace occlusion {
namespace {

// The public readers, each given the same path.
std::vector<std::pair<std::string, std::function<void(const std::string&)>>> readers() {
  return {{"read_file_bytes", [](const std::string& p) { read_file_bytes(p); }},
          {"read_cloud", [](const std::string& p) { read_cloud(p); }},
          {"read_label_file", [](const std::string& p) { read_label_file(p); }},
          {"read_obj", [](const std::string& p) { read_obj(p); }},
          {"read_polygons", [](const std::string& p) { read_polygons(p); }}};
}

TEST(FileBytes, ReadsARegularFileWhole) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bytes.bin");
  const std::string bytes = std::string("a\0b\r\n", 5) + std::string(200000, 'x');
  testing::write_text(path, bytes);
  EXPECT_EQ(read_file_bytes(path), bytes);
}

TEST(FileBytes, FifoIsRefusedWithoutBlocking) {
  testing::ScratchDirectory dir;
  for (const std::string name : {"pipe.txt", "pipe.pcd", "pipe.ply", "pipe.obj"}) {
    const std::string path = dir.file(name);
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    for (const auto& [reader, read] : readers()) {
      if (reader == "read_cloud" && name.substr(name.size() - 4) == ".obj") continue;
      SCOPED_TRACE(reader + " " + name);
      // A structured binding is captured by name (C++17 cannot capture it).
      testing::expect_input_error([&, &read = read] { read(path); }, name, 0,
                                  "is a FIFO (named pipe), not a regular file");
    }
  }
}

TEST(FileBytes, DeviceIsRefusedNotReadForever) {
  testing::ScratchDirectory dir;
  // /dev/zero under each reader's extension, as a user's link might be.
  for (const std::string name : {"zero.txt", "zero.pcd", "zero.ply", "zero.obj"}) {
    const std::string path = dir.file(name);
    std::filesystem::create_symlink("/dev/zero", path);
    for (const auto& [reader, read] : readers()) {
      if (reader == "read_cloud" && name.substr(name.size() - 4) == ".obj") continue;
      SCOPED_TRACE(reader + " " + name);
      testing::expect_input_error([&, &read = read] { read(path); }, name, 0,
                                  "is a character device, not a regular file");
    }
  }
}

TEST(FileBytes, LabelFileSnifferRefusesAFifo) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("labels.txt");
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  testing::expect_input_error([&] { is_label_file(path); }, "labels.txt", 0,
                              "is a FIFO (named pipe), not a regular file");
}

TEST(FileBytes, DirectoryAndMissingFileAreInputErrors) {
  testing::ScratchDirectory dir;
  std::filesystem::create_directories(dir.file("folder.obj"));
  testing::expect_input_error([&] { read_obj(dir.file("folder.obj")); }, "folder.obj", 0,
                              "is a directory, not a regular file");
  testing::expect_input_error([&] { read_file_bytes(dir.file("missing.txt")); }, "missing.txt", 0,
                              "cannot open: No such file or directory");
}

}  // namespace
}  // namespace occlusion
