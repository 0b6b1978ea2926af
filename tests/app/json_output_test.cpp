// format_json always writes valid JSON, even for strings that are not UTF-8
// (Linux file names are bytes; `--json` reports carry them).

#include "occlusion/app/json_output.hpp"

#include <gtest/gtest.h>
#include <json/reader.h>

#include <memory>
#include <string>

namespace occlusion {
namespace {

const std::string kReplacement = "\xEF\xBF\xBD";

TEST(ValidUtf8, KeepsWellFormedText) {
  const std::string text = "plain, caf\xC3\xA9, \xE2\x82\xAC, \xF0\x9F\x98\x80";
  EXPECT_EQ(valid_utf8(text), text);
}

TEST(ValidUtf8, ReplacesEachInvalidByte) {
  // Latin-1 "é", a lone continuation byte, an overlong "/", a surrogate,
  // beyond U+10FFFF and a sequence cut off at the end.
  EXPECT_EQ(valid_utf8("caf\xE9"), "caf" + kReplacement);
  EXPECT_EQ(valid_utf8("a\x80z"), "a" + kReplacement + "z");
  EXPECT_EQ(valid_utf8("\xC0\xAF"), kReplacement + kReplacement);
  EXPECT_EQ(valid_utf8("\xED\xA0\x80"), kReplacement + kReplacement + kReplacement);
  EXPECT_EQ(valid_utf8("\xF4\x90\x80\x80"),
            kReplacement + kReplacement + kReplacement + kReplacement);
  EXPECT_EQ(valid_utf8("x\xE2\x82"), "x" + kReplacement + kReplacement);
}

TEST(PrintableText, ReplacesInvalidUtf8AndControlCharacters) {
  const std::string text = "r\xC3\xA9sum\xC3\xA9 \xE2\x80\x94 tab\tkept | 25 %";
  EXPECT_EQ(printable_text(text), text);
  // A segmenter's binary output: invalid bytes, NUL, an escape sequence, DEL,
  // and U+009B (the C1 control sequence introducer), each one replacement.
  EXPECT_EQ(printable_text(std::string("a\xFF") + '\0' + "b\x1B[31mc\x7F\xC2\x9B"),
            "a" + kReplacement + kReplacement + "b" + kReplacement + "[31mc" + kReplacement +
                kReplacement);
  EXPECT_EQ(printable_text("line\nbreak\r"), "line" + kReplacement + "break" + kReplacement);
  EXPECT_EQ(printable_text("\xC2\xA0nbsp"), "\xC2\xA0nbsp");  // U+00A0 is text
}

TEST(FormatJson, NonUtf8StringsAndKeysStillParse) {
  Json::Value report(Json::objectValue);
  report["input"] = "/data/r\xE9union/scan.pcd";
  report["files"].append("ok.ply");
  report["files"].append("\xFF\xFE.ply");
  report["by_name"]["bad\x80key"] = 1;

  const std::string text = format_json(report);
  Json::CharReaderBuilder builder;
  builder["failIfExtra"] = true;
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  Json::Value parsed;
  std::string errors;
  ASSERT_TRUE(reader->parse(text.data(), text.data() + text.size(), &parsed, &errors)) << errors;
  EXPECT_EQ(valid_utf8(text), text);
  EXPECT_EQ(parsed["input"].asString(), "/data/r" + kReplacement + "union/scan.pcd");
  EXPECT_EQ(parsed["files"][0].asString(), "ok.ply");
  EXPECT_EQ(parsed["files"][1].asString(), kReplacement + kReplacement + ".ply");
  EXPECT_EQ(parsed["by_name"]["bad" + kReplacement + "key"].asInt(), 1);
}

}  // namespace
}  // namespace occlusion
