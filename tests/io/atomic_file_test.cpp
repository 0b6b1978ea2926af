#include "occlusion/io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/scratch_directory.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {
namespace {

using testing::read_bytes;
using testing::ScratchDirectory;
using testing::write_text;

TEST(AtomicFile, WritesANewFile) {
  ScratchDirectory dir;
  const std::string path = dir.file("out.txt");
  write_file_atomically(path, [](std::ostream& out) { out << "hello\n"; });
  EXPECT_EQ(read_bytes(path), "hello\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.txt"}));
}

TEST(AtomicFile, OverwritesAnExistingFile) {
  ScratchDirectory dir;
  const std::string path = dir.file("out.txt");
  write_text(path, "a much longer old content that must not survive\n");
  write_file_atomically(path, [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(read_bytes(path), "new");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.txt"}));
}

TEST(AtomicFile, WritesBinaryBytesUnchanged) {
  ScratchDirectory dir;
  const std::string path = dir.file("out.bin");
  const std::string bytes("\x00\n\r\n\xff", 5);
  write_file_atomically(path, [&](std::ostream& out) { out.write(bytes.data(), 5); });
  EXPECT_EQ(read_bytes(path), bytes);
}

TEST(AtomicFile, ThrowingWriterLeavesTargetUnchangedAndNoTemporary) {
  ScratchDirectory dir;
  const std::string path = dir.file("out.txt");
  write_text(path, "old");
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw std::runtime_error("writer failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_bytes(path), "old");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.txt"}));
}

TEST(AtomicFile, WriterExceptionPropagatesUnchanged) {
  ScratchDirectory dir;
  try {
    write_file_atomically(dir.file("x"),
                          [](std::ostream&) { throw std::out_of_range("specific"); });
    ADD_FAILURE() << "no exception";
  } catch (const std::out_of_range& error) {
    EXPECT_STREQ(error.what(), "specific");
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, FailedStreamIsAnOutputErrorAndLeavesNothing) {
  ScratchDirectory dir;
  const std::string path = dir.file("out.txt");
  write_text(path, "old");
  EXPECT_THROW(
      write_file_atomically(path, [](std::ostream& out) { out.setstate(std::ios::badbit); }),
      OutputError);
  EXPECT_EQ(read_bytes(path), "old");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.txt"}));
}

TEST(AtomicFile, MissingDirectoryIsAnOutputErrorNamingThePath) {
  ScratchDirectory dir;
  const std::string path = dir.file("no/such/dir/out.txt");
  try {
    write_file_atomically(path, [](std::ostream& out) { out << "x"; });
    ADD_FAILURE() << "no error";
  } catch (const OutputError& error) {
    EXPECT_EQ(error.path, path);
    EXPECT_EQ(std::string(error.what()).rfind(path + ": ", 0), 0u) << error.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, TargetThatIsADirectoryIsAnOutputError) {
  ScratchDirectory dir;
  std::filesystem::create_directory(dir.file("taken"));
  EXPECT_THROW(write_file_atomically(dir.file("taken"), [](std::ostream& out) { out << "x"; }),
               OutputError);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"taken"}));
  EXPECT_TRUE(std::filesystem::is_directory(dir.file("taken")));
}

TEST(EnsureDirectory, CreatesNestedDirectories) {
  ScratchDirectory dir;
  const std::string nested = dir.file("a/b/c");
  ensure_directory(nested);
  EXPECT_TRUE(std::filesystem::is_directory(nested));
  EXPECT_NO_THROW(ensure_directory(nested));  // already there
}

TEST(EnsureDirectory, ExistingFileIsAnOutputError) {
  ScratchDirectory dir;
  const std::string path = dir.file("file");
  write_text(path, "x");
  try {
    ensure_directory(path);
    ADD_FAILURE() << "no error";
  } catch (const OutputError& error) {
    EXPECT_EQ(error.path, path);
    EXPECT_NE(std::string(error.what()).find("not a directory"), std::string::npos);
  }
  EXPECT_THROW(ensure_directory(path + "/below"), OutputError);
}

std::vector<std::string> sorted_entries(const ScratchDirectory& dir) {
  std::vector<std::string> names = dir.entries();
  std::sort(names.begin(), names.end());
  return names;
}

void write_through(OutputSet& outputs, const std::string& target, const std::string& text) {
  write_file_atomically(outputs.add(target), [&](std::ostream& out) { out << text; });
}

TEST(OutputSet, CommitReplacesEveryFileAtOnce) {
  ScratchDirectory dir;
  write_text(dir.file("a.ply"), "old a");
  write_text(dir.file("b.json"), "old b");
  OutputSet outputs;
  write_through(outputs, dir.file("a.ply"), "new a");
  write_through(outputs, dir.file("b.json"), "new b");
  // Nothing shows before commit.
  EXPECT_EQ(read_bytes(dir.file("a.ply")), "old a");
  EXPECT_EQ(read_bytes(dir.file("b.json")), "old b");
  outputs.commit();
  EXPECT_EQ(read_bytes(dir.file("a.ply")), "new a");
  EXPECT_EQ(read_bytes(dir.file("b.json")), "new b");
  EXPECT_EQ(sorted_entries(dir), (std::vector<std::string>{"a.ply", "b.json"}));
}

TEST(OutputSet, TemporaryNamesKeepTheExtension) {
  ScratchDirectory dir;
  OutputSet outputs;
  const std::string temporary = outputs.add(dir.file("scene.scan.pcd"));
  EXPECT_EQ(std::filesystem::path(temporary).extension(), ".pcd");
  EXPECT_EQ(std::filesystem::path(temporary).parent_path(), dir.path());
  EXPECT_EQ(std::filesystem::path(temporary).filename().string()[0], '.');
}

TEST(OutputSet, AFailureMidSetLeavesTheOldSetAndNoTemporary) {
  ScratchDirectory dir;
  write_text(dir.file("a.ply"), "old a");
  write_text(dir.file("b.json"), "old b");
  {
    OutputSet outputs;
    write_through(outputs, dir.file("a.ply"), "new a");
    EXPECT_THROW(write_file_atomically(outputs.add(dir.file("b.json")),
                                       [](std::ostream&) { throw std::runtime_error("killed"); }),
                 std::runtime_error);
  }
  EXPECT_EQ(read_bytes(dir.file("a.ply")), "old a");
  EXPECT_EQ(read_bytes(dir.file("b.json")), "old b");
  EXPECT_EQ(sorted_entries(dir), (std::vector<std::string>{"a.ply", "b.json"}));
}

TEST(OutputSet, RefusesBeforeRenamingWhenATargetIsAFolderOrAFileIsMissing) {
  ScratchDirectory dir;
  write_text(dir.file("a.ply"), "old a");
  std::filesystem::create_directories(dir.file("b.json/inside"));
  {
    OutputSet outputs;
    write_through(outputs, dir.file("a.ply"), "new a");
    write_through(outputs, dir.file("b.json"), "new b");
    EXPECT_THROW(outputs.commit(), OutputError);
  }
  EXPECT_EQ(read_bytes(dir.file("a.ply")), "old a");
  {
    OutputSet outputs;
    write_through(outputs, dir.file("a.ply"), "new a");
    outputs.add(dir.file("c.csv"));  // never written
    EXPECT_THROW(outputs.commit(), OutputError);
  }
  EXPECT_EQ(read_bytes(dir.file("a.ply")), "old a");
  EXPECT_EQ(sorted_entries(dir), (std::vector<std::string>{"a.ply", "b.json"}));
  OutputSet twice;
  twice.add(dir.file("a.ply"));
  EXPECT_THROW(twice.add(dir.file("a.ply")), OutputError);
}

}  // namespace
}  // namespace occlusion
