// A process killed (SIGKILL) at each point of an output set's commit, and the
// sweep that makes the folder consistent again: the previous set or the new
// one, whole, and no temporaries of dead processes.

#include "occlusion/io/output_recovery.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "io/scratch_directory.hpp"
#include "occlusion/io/atomic_file.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::ScratchDirectory;
using testing::write_text;

const std::vector<std::string> kNames = {"room.moc.json", "room.moc.ply", "room.moc.csv"};

std::vector<std::string> sorted_entries(const ScratchDirectory& dir) {
  std::vector<std::string> names = dir.entries();
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> sorted_names() {
  std::vector<std::string> names = kNames;
  std::sort(names.begin(), names.end());
  return names;
}

void write_old_set(const ScratchDirectory& dir) {
  for (const auto& name : kNames) write_text(dir.file(name), "old " + name);
}

// Kill points of a commit, in the order OutputSet::commit passes them.
enum class KillPoint { kBeforeManifest, kAfterManifest, kAfterOneRename, kAfterAllRenames };

// A child process writes a new set with OutputSet's own temporary names and
// its manifest, renames as commit does, and is killed with SIGKILL at `point`.
void kill_while_committing(const ScratchDirectory& dir, KillPoint point) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    OutputSet outputs;
    std::vector<std::pair<std::string, std::string>> files;
    for (const auto& name : kNames) {
      files.emplace_back(outputs.add(dir.file(name)), dir.file(name));
      write_text(files.back().first, "new " + name);
    }
    if (point != KillPoint::kBeforeManifest) {
      write_commit_manifest(commit_manifest_path(dir.path().string(), ::getpid(), 99), files);
      const std::size_t renames = point == KillPoint::kAfterOneRename    ? 1
                                  : point == KillPoint::kAfterAllRenames ? files.size()
                                                                         : 0;
      for (std::size_t i = 0; i < renames; ++i) fs::rename(files[i].first, files[i].second);
    }
    ::raise(SIGKILL);
    ::_exit(1);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
}

void expect_set(const ScratchDirectory& dir, const std::string& version) {
  EXPECT_EQ(sorted_entries(dir), sorted_names());
  for (const auto& name : kNames) EXPECT_EQ(read_bytes(dir.file(name)), version + " " + name);
}

TEST(OutputRecovery, KilledWhileWritingLeavesThePreviousSetAndTheSweepRemovesItsTemporaries) {
  ScratchDirectory dir;
  write_old_set(dir);
  kill_while_committing(dir, KillPoint::kBeforeManifest);
  EXPECT_EQ(dir.entries().size(), 2 * kNames.size());  // the temporaries stayed
  const RecoveredOutputs recovered = recover_outputs(dir.path().string());
  EXPECT_EQ(recovered.removed_temporaries, kNames.size());
  EXPECT_EQ(recovered.completed_sets, 0u);
  expect_set(dir, "old");
}

TEST(OutputRecovery, KilledAfterTheManifestTheSweepCommitsTheNewSet) {
  ScratchDirectory dir;
  write_old_set(dir);
  kill_while_committing(dir, KillPoint::kAfterManifest);
  EXPECT_EQ(recover_outputs(dir.path().string()).completed_sets, 1u);
  expect_set(dir, "new");
}

TEST(OutputRecovery, KilledBetweenRenamesTheSweepFinishesThem) {
  ScratchDirectory dir;
  write_old_set(dir);
  kill_while_committing(dir, KillPoint::kAfterOneRename);
  // Mixed: the first output is new, the others old.
  EXPECT_EQ(read_bytes(dir.file(kNames[0])), "new " + kNames[0]);
  EXPECT_EQ(read_bytes(dir.file(kNames[1])), "old " + kNames[1]);
  recover_outputs(dir.path().string());
  expect_set(dir, "new");
}

TEST(OutputRecovery, KilledAfterTheRenamesTheSweepRemovesTheManifest) {
  ScratchDirectory dir;
  kill_while_committing(dir, KillPoint::kAfterAllRenames);
  EXPECT_EQ(dir.entries().size(), kNames.size() + 1);
  recover_outputs(dir.path().string());
  expect_set(dir, "new");
}

TEST(OutputRecovery, AnOutputWrittenSinceTheKillIsNotReplacedByTheOlderSet) {
  ScratchDirectory dir;
  write_old_set(dir);
  kill_while_committing(dir, KillPoint::kAfterOneRename);
  write_text(dir.file(kNames[2]), "later");
  fs::last_write_time(dir.file(kNames[2]),
                      fs::file_time_type::clock::now() + std::chrono::seconds(10));
  recover_outputs(dir.path().string());
  EXPECT_EQ(sorted_entries(dir), sorted_names());
  EXPECT_EQ(read_bytes(dir.file(kNames[1])), "new " + kNames[1]);
  EXPECT_EQ(read_bytes(dir.file(kNames[2])), "later");
}

TEST(OutputRecovery, ARunningProcesssFilesAreLeftAlone) {
  ScratchDirectory dir;
  write_old_set(dir);
  // The parent (the test runner) and this process run: their files may be in use.
  std::vector<std::string> live;
  for (const long pid : {static_cast<long>(::getppid()), static_cast<long>(::getpid())}) {
    live.push_back(".tmp-" + std::to_string(pid) + "-0-" + kNames[0]);
    write_text(dir.file(live.back()), "in progress");
    live.push_back(".commit-" + std::to_string(pid) + "-1");
    write_text(dir.file(live.back()), "occlusion output set 1\n");
  }
  const RecoveredOutputs recovered = recover_outputs(dir.path().string());
  EXPECT_EQ(recovered.removed_temporaries, 0u);
  EXPECT_EQ(recovered.completed_sets, 0u);
  for (const auto& name : live) EXPECT_TRUE(fs::exists(dir.file(name))) << name;
}

TEST(OutputRecovery, TheNextCommitInTheFolderSweepsFirst) {
  ScratchDirectory dir;
  write_old_set(dir);
  kill_while_committing(dir, KillPoint::kAfterOneRename);
  {
    OutputSet outputs;
    write_text(outputs.add(dir.file(kNames[1])), "newest");
    write_text(outputs.add(dir.file("other.csv")), "other");
    outputs.commit();
  }
  std::vector<std::string> expected = kNames;
  expected.push_back("other.csv");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(sorted_entries(dir), expected);
  EXPECT_EQ(read_bytes(dir.file(kNames[0])), "new " + kNames[0]);
  EXPECT_EQ(read_bytes(dir.file(kNames[1])), "newest");
  EXPECT_EQ(read_bytes(dir.file(kNames[2])), "new " + kNames[2]);
}

TEST(OutputRecovery, ACommitLeavesNoManifestBehind) {
  ScratchDirectory dir;
  OutputSet outputs;
  for (const auto& name : kNames) write_text(outputs.add(dir.file(name)), "new " + name);
  outputs.commit();
  expect_set(dir, "new");
}

TEST(OutputRecovery, ASetNamedRelativeToTheWorkingDirectoryCommitsAndSweeps) {
  ScratchDirectory dir;
  const fs::path before = fs::current_path();
  fs::current_path(dir.path());
  {
    OutputSet outputs;
    for (const auto& name : kNames) write_text(outputs.add(name), "new " + name);
    outputs.commit();
  }
  recover_outputs("");
  fs::current_path(before);
  expect_set(dir, "new");
}

}  // namespace
}  // namespace occlusion
