// The viewer and the WebSocket share one port: plain HTTP over a real socket.

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

// One request, the whole response (the server closes after it), 5 s at most.
std::string http(std::uint16_t port, const std::string& request) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return "";
  timeval timeout{5, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  std::string response;
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      ::send(fd, request.data(), request.size(), 0) == static_cast<ssize_t>(request.size())) {
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) {
      response.append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  return response;
}

std::string get(std::uint16_t port, const std::string& target) {
  return http(port, "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
}

TEST(Http, ServesTheBuiltViewerBesideTheWebSocket) {
  const TestData scratch;
  const std::string web = scratch.root() + "/web";
  std::filesystem::create_directories(web + "/assets");
  std::ofstream(web + "/index.html") << "<html>the viewer</html>";
  std::ofstream(web + "/assets/main.js") << "export {}";
  server::ServerOptions options = TestServer::quiet_options();
  options.web_dir = web;
  TestServer server(options);

  std::string response = get(server.port(), "/");
  EXPECT_EQ(response.rfind("HTTP/1.1 200", 0), 0u) << response;
  EXPECT_NE(response.find("Content-Type: text/html; charset=utf-8"), std::string::npos);
  EXPECT_NE(response.find("<html>the viewer</html>"), std::string::npos);
  response = get(server.port(), "/assets/main.js");
  EXPECT_NE(response.find("Content-Type: text/javascript"), std::string::npos) << response;
  EXPECT_EQ(get(server.port(), "/../../etc/passwd").rfind("HTTP/1.1 403", 0), 0u);
  EXPECT_EQ(get(server.port(), "/nope.js").rfind("HTTP/1.1 404", 0), 0u);
  EXPECT_EQ(http(server.port(),
                 "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 0\r\n"
                 "Connection: close\r\n\r\n")
                .rfind("HTTP/1.1 405", 0),
            0u);
  // The WebSocket on the same port is unaffected.
  EXPECT_TRUE(server.connect()->request(1, "ping").ok());
}

TEST(Http, WithoutAViewerExplainsHowToBuildIt) {
  TestServer server;
  const std::string response = get(server.port(), "/");
  EXPECT_EQ(response.rfind("HTTP/1.1 200", 0), 0u) << response;
  EXPECT_NE(response.find("npm run build"), std::string::npos);
}

}  // namespace
}  // namespace occlusion::testing
