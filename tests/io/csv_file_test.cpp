#include "occlusion/io/csv_file.hpp"

#include <gtest/gtest.h>

#include "io/scratch_directory.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {
namespace {

using testing::read_bytes;
using testing::ScratchDirectory;
using testing::write_text;

TEST(CsvFile, RoundTripsFieldsThatNeedQuotes) {
  const ScratchDirectory dir;
  CsvTable table;
  table.columns = {"scene", "segmenter", "miou"};
  table.rows = {{"office_1", "baseline (geometric, region-growing planes)", "0.25"},
                {"a \"quoted\" name", "python infer.py {input}\n{output}", ""}};
  write_csv(dir.file("t.csv"), table);
  EXPECT_EQ(read_bytes(dir.file("t.csv")).substr(0, 24), "scene,segmenter,miou\noff");
  const CsvTable back = read_csv(dir.file("t.csv"));
  EXPECT_EQ(back.columns, table.columns);
  EXPECT_EQ(back.rows, table.rows);
  EXPECT_EQ(back.column("miou"), 2u);
  EXPECT_EQ(back.column("none"), 3u);
}

TEST(CsvFile, AcceptsCrlfAndAByteOrderMark) {
  const ScratchDirectory dir;
  write_text(dir.file("t.csv"),
             "\xEF\xBB\xBF"
             "a,b\r\n1,\"x,y\"\r\n\r\n");
  const CsvTable table = read_csv(dir.file("t.csv"));
  EXPECT_EQ(table.columns, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.rows[0], (std::vector<std::string>{"1", "x,y"}));
}

TEST(CsvFile, MalformedFilesNameTheLine) {
  const ScratchDirectory dir;
  write_text(dir.file("width.csv"), "a,b\n1,2\n3\n");
  try {
    read_csv(dir.file("width.csv"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line, 3u);
  }
  write_text(dir.file("quote.csv"), "a,b\n1,\"open\n");
  EXPECT_THROW(read_csv(dir.file("quote.csv")), InputError);
  write_text(dir.file("after.csv"), "a,b\n\"x\"y,2\n");
  EXPECT_THROW(read_csv(dir.file("after.csv")), InputError);
  write_text(dir.file("empty.csv"), "");
  EXPECT_THROW(read_csv(dir.file("empty.csv")), InputError);
}

}  // namespace
}  // namespace occlusion
