// The server's pieces that need no socket: binary frames, path confinement,
// static files.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "occlusion/server/binary_frame.hpp"
#include "occlusion/server/data_root.hpp"
#include "occlusion/server/protocol_error.hpp"
#include "occlusion/server/server.hpp"
#include "occlusion/server/static_files.hpp"
#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

namespace fs = std::filesystem;
using server::ProtocolError;

std::string error_code_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const ProtocolError& e) {
    return e.code;
  }
  return "";
}

TEST(BinaryFrame, HeaderLayoutIsTheDocumentedOne) {
  const float values[6] = {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f};
  server::Frame frame = server::make_frame(server::FrameKind::kPositions, values, 2, 3, 7);
  server::set_request_id(frame.message, 0x01020304);
  const std::string& m = frame.message;
  ASSERT_EQ(m.size(), 32u + 24u);
  EXPECT_EQ(m.substr(0, 4), "OCCB");
  EXPECT_EQ(m[4], 1);  // version, little-endian
  EXPECT_EQ(m[5], 0);
  EXPECT_EQ(m[6], 1);  // kind positions
  EXPECT_EQ(m[8], 4);  // request id, little-endian
  EXPECT_EQ(m[11], 1);
  EXPECT_EQ(m[12], 5);  // float32
  EXPECT_EQ(m[13], 3);  // components
  EXPECT_EQ(m[16], 2);  // count
  EXPECT_EQ(m[24], 7);  // item
  const server::FrameHeader header = server::decode_frame_header(m);
  EXPECT_EQ(header.request_id, 0x01020304u);
  EXPECT_EQ(header.count, 2u);
  EXPECT_EQ(frame_values<float>(m), std::vector<float>(values, values + 6));
  EXPECT_EQ(server::describe(header)["kind"].asString(), "positions");
}

TEST(BinaryFrame, MalformedHeadersAreRefused) {
  const std::uint8_t bytes[4] = {1, 2, 3, 4};
  const std::string good = server::make_frame(server::FrameKind::kUpload, bytes, 4, 1).message;
  EXPECT_EQ(error_code_of([&] { server::decode_frame_header(good.substr(0, 31)); }),
            "unexpected_binary");
  EXPECT_EQ(error_code_of([&] { server::decode_frame_header(good.substr(0, 35)); }),
            "unexpected_binary");
  std::string bad_type = good;
  bad_type[12] = 9;
  EXPECT_EQ(error_code_of([&] { server::decode_frame_header(bad_type); }), "unexpected_binary");
  std::string huge_count = good;
  for (int b = 16; b < 24; ++b) huge_count[static_cast<std::size_t>(b)] = '\xff';
  EXPECT_EQ(error_code_of([&] { server::decode_frame_header(huge_count); }), "unexpected_binary");
  EXPECT_NO_THROW(server::decode_frame_header(good));
}

TEST(DataRoot, ConfinesPathsToTheDataDirectory) {
  const TestData files;
  const server::DataRoot root(files.data());
  EXPECT_EQ(root.resolve("sample_room.obj", true), fs::canonical(files.file("sample_room.obj")));
  EXPECT_EQ(root.resolve("", true), fs::canonical(files.data()));
  EXPECT_EQ(root.resolve("s3dis_synthetic/../sample_room.obj", true),
            fs::canonical(files.file("sample_room.obj")));
  EXPECT_EQ(root.resolve("new/folder/file.txt", false),
            fs::canonical(files.data()) / "new/folder/file.txt");
  for (const char* outside : {"..", "../outside/secret.txt", "/etc/passwd", "escape",
                              "escape/secret.txt", "nothing/../../outside"}) {
    EXPECT_EQ(error_code_of([&] { root.resolve(outside, false); }), "path_outside_data") << outside;
  }
  EXPECT_EQ(error_code_of([&] { root.resolve("missing.obj", true); }), "not_found");
  // Through the link and back in: where it leads counts, not how it is spelt.
  EXPECT_EQ(root.resolve("escape/../data/sample_room.obj", true),
            fs::canonical(files.file("sample_room.obj")));
  EXPECT_EQ(root.relative(root.resolve("s3dis_synthetic/openings.txt", true).string()),
            "s3dis_synthetic/openings.txt");
  EXPECT_EQ(root.relative("/etc/passwd"), "/etc/passwd");
  EXPECT_THROW(server::DataRoot(files.file("sample_room.obj")), std::invalid_argument);
}

// A path a file names (a depth frame's image) is taken from that file's
// folder and held to the same rule as a client's.
TEST(DataRoot, ConfinesThePathsAFileNames) {
  const TestData files;
  const server::DataRoot root(files.data());
  const std::string file = root.resolve("s3dis_synthetic/openings.txt", true).string();
  EXPECT_EQ(root.resolve_named(file, "Area_1"), root.resolve("s3dis_synthetic/Area_1", true));
  EXPECT_EQ(root.resolve_named(file, "../sample_room.obj"), root.resolve("sample_room.obj", true));
  EXPECT_EQ(root.resolve_named(file, "not/yet.png"),
            fs::canonical(files.data()) / "s3dis_synthetic/not/yet.png");
  for (const std::string& outside :
       {std::string("../../outside/secret.txt"), std::string("../escape/secret.txt"),
        files.root() + "/outside/secret.txt", files.file("sample_room.obj"),
        std::string("../../outside/missing.png")}) {
    EXPECT_EQ(error_code_of([&] { root.resolve_named(file, outside); }), "path_outside_data")
        << outside;
  }
}

// A sentence naming files of the data directory (a depth frame's warning
// names its image, which resolve_named made absolute) names them as the
// client does; a path that merely contains the directory's name is kept.
TEST(DataRoot, NamesItsFilesRelativeWithinASentence) {
  const TestData files;
  const server::DataRoot root(files.data());
  const std::string data = fs::canonical(files.data()).string();
  EXPECT_EQ(root.relative_in(data + "/a.frame.json: depths of " + data + "/images/a.png lie"),
            "a.frame.json: depths of images/a.png lie");
  EXPECT_EQ(root.relative_in("reads '" + data + "/x.png' (" + data + "/y.png)"),
            "reads 'x.png' (y.png)");
  EXPECT_EQ(root.relative_in("/elsewhere" + data + "/x.png"), "/elsewhere" + data + "/x.png");
  EXPECT_EQ(root.relative_in("no path here"), "no path here");
  EXPECT_EQ(root.relative_in(data), "");
  Json::Value json(Json::objectValue);
  json["warnings"].append("see " + data + "/b.png");
  root.relativise(json);
  EXPECT_EQ(json["warnings"][0].asString(), "see b.png");
}

TEST(StaticFiles, ServesTheViewerAndNothingElse) {
  const TestData files;
  const std::string web = files.root() + "/web";
  fs::create_directories(web + "/assets");
  std::ofstream(web + "/index.html") << "<html>viewer</html>";
  std::ofstream(web + "/assets/app.js") << "console.log(1)";
  std::ofstream(web + "/assets/my file.css") << "body{}";
  fs::create_symlink(files.root() + "/outside/secret.txt", web + "/assets/secret.txt");
  const server::StaticFiles served(web);
  ASSERT_TRUE(served.has_viewer());

  auto response = served.get("/");
  EXPECT_EQ(response.status, 200);
  EXPECT_EQ(response.body, "<html>viewer</html>");
  EXPECT_EQ(response.content_type, "text/html; charset=utf-8");
  response = served.get("/assets/app.js?v=3");
  EXPECT_EQ(response.status, 200);
  EXPECT_EQ(response.content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(served.get("/assets/my%20file.css").status, 200);
  EXPECT_EQ(served.get("/missing.js").status, 404);
  EXPECT_EQ(served.get("/../outside/secret.txt").status, 403);
  EXPECT_EQ(served.get("/%2e%2e/outside/secret.txt").status, 403);
  EXPECT_EQ(served.get("/assets/secret.txt").status, 403);
  EXPECT_EQ(served.get("/a%00b").status, 400);

  const server::StaticFiles none(files.root() + "/no-such-web");
  EXPECT_FALSE(none.has_viewer());
  response = none.get("/");
  EXPECT_EQ(response.status, 200);
  EXPECT_NE(response.body.find("npm run build"), std::string::npos);
  EXPECT_EQ(none.get("/app.js").status, 404);
}

TEST(Server, RefusesForeignAndReboundOrigins) {
  using server::origin_allowed;
  EXPECT_TRUE(origin_allowed("", "127.0.0.1:8080", "127.0.0.1"));  // not a browser
  EXPECT_TRUE(origin_allowed("http://127.0.0.1:8080", "127.0.0.1:8080", "127.0.0.1"));
  EXPECT_TRUE(origin_allowed("http://localhost:5173", "127.0.0.1:8080", "127.0.0.1"));
  EXPECT_TRUE(origin_allowed("http://[::1]:8080", "[::1]:8080", "::1"));
  EXPECT_TRUE(origin_allowed("http://192.168.1.10:8080", "192.168.1.10:8080", "0.0.0.0"));
  EXPECT_TRUE(origin_allowed("http://lab-pc:8080", "lab-pc:8080", "lab-pc"));
  EXPECT_FALSE(origin_allowed("http://evil.example", "127.0.0.1:8080", "127.0.0.1"));
  // DNS rebinding: evil.example now resolves to 127.0.0.1, so the browser
  // sends its own name as both Origin and Host.
  EXPECT_FALSE(origin_allowed("http://evil.example:8080", "evil.example:8080", "127.0.0.1"));
  EXPECT_FALSE(origin_allowed("http://evil.example:8080", "evil.example:8080", "0.0.0.0"));
  EXPECT_FALSE(origin_allowed("null", "127.0.0.1:8080", "127.0.0.1"));
}

TEST(Server, KnowsWhichHostsAreLoopback) {
  for (const char* host : {"127.0.0.1", "127.4.5.6", "::1", "localhost"}) {
    EXPECT_TRUE(server::is_loopback_host(host)) << host;
  }
  for (const char* host : {"0.0.0.0", "::", "192.168.1.10", "example.org", ""}) {
    EXPECT_FALSE(server::is_loopback_host(host)) << host;
  }
}

TEST(Server, RefusesAMissingDataDirectory) {
  server::ServerOptions options = TestServer::quiet_options();
  options.port = 0;
  options.data_dir = "/no/such/directory";
  EXPECT_THROW(server::Server{options}, std::invalid_argument);
}

// A server killed (SIGKILL) while it committed a job's outputs leaves its
// temporaries in DATA/out; the next server sweeps them at start.
TEST(Server, StartSweepsTheOutputsOfADeadProcess) {
  const TestData files;
  fs::create_directories(files.file("out"));
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // a PID that no longer runs
  const std::string dead = files.file("out/.tmp-" + std::to_string(child) + "-0-room.moc.json");
  const std::string live =
      files.file("out/.tmp-" + std::to_string(::getppid()) + "-0-room.moc.json");
  std::ofstream(dead) << "half";
  std::ofstream(live) << "in progress";
  server::ServerOptions options = TestServer::quiet_options();
  options.port = 0;
  options.data_dir = files.data();
  const server::Server server(options);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
}

}  // namespace
}  // namespace occlusion::testing
