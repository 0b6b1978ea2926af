// File names are bytes; JSON is UTF-8. list_files must stay usable when a
// folder holds a name that is not UTF-8 (issue 13): every listed path opens,
// and the entries it cannot name are counted.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

TEST(NonUtf8Names, ListFilesListsWhatItCanNameAndCountsTheRest) {
  TestServer server;
  const std::string folder = server.files().file("names");
  std::filesystem::create_directories(folder);
  for (const std::string name : {"ok.obj", "r\xE9union.obj", "\xFF\xFE.ply", "caf\xC3\xA9.txt"}) {
    std::ofstream(folder + "/" + name) << "v 0 0 0\n";
  }
  const auto client = server.connect();
  const Reply reply = client->request(1, "list_files", params(R"({"dir": "names"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  std::set<std::string> names;
  for (const auto& entry : reply.final["result"]["entries"]) {
    names.insert(entry["name"].asString());
    EXPECT_TRUE(std::filesystem::exists(server.files().file(entry["path"].asString())))
        << entry["path"].asString();
  }
  EXPECT_EQ(names, (std::set<std::string>{"ok.obj", "caf\xC3\xA9.txt"}));
  EXPECT_EQ(reply.final["result"]["not_utf8"].asUInt(), 2u);
}

}  // namespace
}  // namespace occlusion::testing
