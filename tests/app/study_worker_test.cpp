// The study's persistent segmenter ("worker: COMMAND"): started once per
// study, one request per run, its failures confined to their runs.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "io/scratch_directory.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_file.hpp"
#include "occlusion/app/study_job.hpp"

namespace occlusion {
namespace {

using testing::read_bytes;
using testing::ScratchDirectory;

const std::string kSource = OCCLUSION_SOURCE_DIR;

// config/study.json (the office from patterns 7, 4 and 1) with few rays.
StudyRequest office_study(const std::string& out) {
  StudyRequest request;
  apply_config(load_config(kSource + "/config/study.json"), "study", study_keys(), request);
  request.tracing.num_rays_per_vp = 400;
  request.out = out;
  return request;
}

// tests/support/study_segmenter.py as a worker (its docstring) that answers
// with the ground truth, appending a line to `starts` each time it starts.
std::string truth_worker(const std::string& starts, const std::string& misbehaviour = "") {
  return "worker: python3 '" + kSource + "/tests/support/study_segmenter.py' serve truth '" +
         starts + "'" + (misbehaviour.empty() ? "" : " " + misbehaviour + " pattern_4");
}

std::size_t lines(const std::string& path) {
  if (!std::filesystem::exists(path)) return 0;
  const std::string text = read_bytes(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::string cell(const CsvTable& table, std::size_t row, const std::string& column) {
  return table.rows.at(row).at(table.column(column));
}

double miou(const CsvTable& table, std::size_t row) {
  return std::stod(cell(table, row, "miou"));
}

// The process whose id a misbehaving worker wrote to STARTS.pid has ended (a
// zombie left to init counts): the study did not leave it running. Waits up
// to a minute for init to reap an orphan; no test depends on how long.
bool worker_is_gone(const std::string& starts) {
  std::ifstream pid_file(starts + ".pid");
  long pid = 0;
  if (!(pid_file >> pid) || pid <= 0) return false;
  const std::string stat = "/proc/" + std::to_string(pid) + "/stat";
  for (int i = 0; i < 600; ++i) {
    std::ifstream file(stat);
    std::string fields;
    if (!std::getline(file, fields)) return true;
    const std::size_t state = fields.rfind(')') + 2;
    if (state < fields.size() && (fields[state] == 'Z' || fields[state] == 'X')) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

TEST(StudyWorker, IsStartedOncePerStudyAndEveryRunScores) {
  const ScratchDirectory dir;
  const std::string starts = dir.file("starts");
  StudyRequest request = office_study(dir.file("study"));
  request.segmenter = truth_worker(starts);
  const StudyReport report = run_study(request);
  ASSERT_EQ(report.table.rows.size(), 3u);
  EXPECT_EQ(report.runs_failed, 0u);
  EXPECT_EQ(lines(starts), 1u);  // three runs, one process
  for (std::size_t r = 0; r < 3; ++r) {
    // The ground truth, paired by position: a perfect score.
    EXPECT_EQ(miou(report.table, r), 1.0) << cell(report.table, r, "failure");
    EXPECT_EQ(cell(report.table, r, "segmenter"), request.segmenter);
  }
  // A study with nothing left to do starts no worker; a fresh one starts one.
  run_study(request);
  EXPECT_EQ(lines(starts), 1u);
  request.fresh = true;
  EXPECT_EQ(run_study(request).runs_failed, 0u);
  EXPECT_EQ(lines(starts), 2u);
}

TEST(StudyWorker, OneThatDiesFailsItsRunAndIsStartedAgainForTheNext) {
  const ScratchDirectory dir;
  const std::string starts = dir.file("starts");
  StudyRequest request = office_study(dir.file("study"));
  request.segmenter = truth_worker(starts, "die");
  const StudyReport report = run_study(request);
  ASSERT_EQ(report.table.rows.size(), 3u);
  EXPECT_EQ(report.runs_failed, 1u);
  EXPECT_EQ(cell(report.table, 0, "status"), "ok");
  EXPECT_EQ(cell(report.table, 1, "status"), "failed");
  EXPECT_EQ(cell(report.table, 2, "status"), "ok");
  const std::string why = cell(report.table, 1, "failure");
  EXPECT_NE(why.find("ended (exit status 9) without answering"), std::string::npos) << why;
  EXPECT_NE(why.find("worker dying"), std::string::npos) << why;
  EXPECT_EQ(miou(report.table, 2), 1.0);
  EXPECT_EQ(lines(starts), 2u);
}

TEST(StudyWorker, OneThatHangsIsKilledAtTheTimeoutAndOneThatRefusesStays) {
  const ScratchDirectory dir;
  const std::string starts = dir.file("starts");
  StudyRequest request = office_study(dir.file("hang"));
  request.segmenter = truth_worker(starts, "hang");
  request.segmenter_timeout = 20.0;  // python's start-up on a loaded machine fits
  // The hung worker sleeps for an hour: the study returns only if it was
  // killed, and the next run's answer comes from a second worker.
  const StudyReport hung = run_study(request);
  ASSERT_EQ(hung.table.rows.size(), 3u);
  EXPECT_EQ(hung.runs_failed, 1u);
  EXPECT_NE(cell(hung.table, 1, "failure").find("did not answer within"), std::string::npos)
      << cell(hung.table, 1, "failure");
  EXPECT_EQ(miou(hung.table, 2), 1.0);
  EXPECT_EQ(lines(starts), 2u);

  const std::string kept = dir.file("kept");
  request.out = dir.file("refuse");
  request.segmenter = truth_worker(kept, "refuse");
  request.segmenter_timeout = 0.0;
  const StudyReport refused = run_study(request);
  EXPECT_EQ(refused.runs_failed, 1u);
  EXPECT_NE(cell(refused.table, 1, "failure").find("answered: cannot segment this"),
            std::string::npos)
      << cell(refused.table, 1, "failure");
  EXPECT_EQ(lines(kept), 1u);  // a refusal is an answer: the worker stays
}

// Issue 44, 2.6: its stdin and stdout were one socket, so closing stdout left
// the socket open through stdin, and with no timeout (the default) the study
// waited forever.
TEST(StudyWorker, OneThatClosesItsStdoutAndStaysFailsItsRunAndIsKilled) {
  const ScratchDirectory dir;
  const std::string starts = dir.file("starts");
  StudyRequest request = office_study(dir.file("study"));
  request.segmenter = truth_worker(starts, "close_stdout");
  ASSERT_EQ(request.segmenter_timeout, 0.0);  // the default: no limit
  const StudyReport report = run_study(request);
  ASSERT_EQ(report.table.rows.size(), 3u);
  EXPECT_EQ(report.runs_failed, 1u);
  const std::string why = cell(report.table, 1, "failure");
  EXPECT_NE(why.find("closed its stdout without answering"), std::string::npos) << why;
  EXPECT_TRUE(worker_is_gone(starts));
  EXPECT_EQ(miou(report.table, 2), 1.0);
  EXPECT_EQ(lines(starts), 2u);
}

// Issue 44, 2.6: the study read a line without end ever slower (it searched
// all it had read for the line break after every 4 KiB) and without bound.
TEST(StudyWorker, OneThatFloodsItsStdoutIsRefusedAtTheCapAndKilled) {
  const ScratchDirectory dir;
  const std::string starts = dir.file("starts");
  StudyRequest request = office_study(dir.file("study"));
  request.segmenter = truth_worker(starts, "flood");
  request.segmenter_timeout = 600.0;  // the cap ends it, not the timeout
  const StudyReport report = run_study(request);
  ASSERT_EQ(report.table.rows.size(), 3u);
  EXPECT_EQ(report.runs_failed, 1u);
  const std::string why = cell(report.table, 1, "failure");
  EXPECT_NE(why.find("bytes on its stdout without a line break"), std::string::npos) << why;
  EXPECT_TRUE(worker_is_gone(starts));
  // What it could write: the cap, plus what the socket holds, far below the
  // gigabytes it would have written were it read to the end.
  std::ifstream flooded(starts + ".flooded");
  std::size_t written = 0;
  ASSERT_TRUE(flooded >> written);
  EXPECT_LT(written, std::size_t{16} << 20);
  EXPECT_EQ(miou(report.table, 2), 1.0);
}

// Issue 44, 2.6: bytes arriving faster than the poll's tick skipped the
// timeout's check, so a worker that never finished its line was never killed.
TEST(StudyWorker, OneThatTricklesWithoutEndingItsLineIsKilledAtTheTimeout) {
  const ScratchDirectory dir;
  const std::string starts = dir.file("starts");
  StudyRequest request = office_study(dir.file("study"));
  request.segmenter = truth_worker(starts, "trickle");
  // Generous for python's start-up on a loaded machine; the trickle (one
  // byte a millisecond) stays far below the cap for that long.
  request.segmenter_timeout = 20.0;
  const StudyReport report = run_study(request);
  ASSERT_EQ(report.table.rows.size(), 3u);
  EXPECT_EQ(report.runs_failed, 1u);
  const std::string why = cell(report.table, 1, "failure");
  EXPECT_NE(why.find("did not answer within"), std::string::npos) << why;
  EXPECT_TRUE(worker_is_gone(starts));
}

TEST(StudyWorker, ACommandWithPlaceholdersOrNoneIsRefused) {
  const ScratchDirectory dir;
  for (const std::string segmenter : {"worker: python3 infer.py {input} {output}", "worker:  "}) {
    StudyRequest request = office_study(dir.file("study"));
    request.segmenter = segmenter;
    EXPECT_THROW(run_study(request), KeyError) << segmenter;
  }
}

}  // namespace
}  // namespace occlusion
