// A text message is refused by the transport (close 1009) as soon as a frame
// header says it passes the text limit, before its bytes are held: only an
// announced upload may be longer. The raw-socket client sends a header that
// promises far more bytes than it ever sends, so the server's close proves it
// did not wait to buffer them. The client sends nothing after that header:
// WebSocket++ drops the connection right after its 1009 close frame, and bytes
// it never read would turn that into a reset that can reach the client before
// it reads the frame (CI saw nullopt where 1009 was sent).

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <optional>

#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

// A WebSocket client over a bare socket that can send frames WebSocket++'s
// client would not: a header whose length the payload never reaches.
class RawWebSocket {
 public:
  explicit RawWebSocket(std::uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd_ < 0) return;
    timeval timeout{60, 0};  // hang guard only: the close comes in milliseconds
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) return;
    send_all(
        "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
    // The handshake's response ends with an empty line; frames follow.
    while (buffer_.find("\r\n\r\n") == std::string::npos) {
      if (!read_more()) return;
    }
    open_ = buffer_.rfind("HTTP/1.1 101", 0) == 0;
    buffer_.erase(0, buffer_.find("\r\n\r\n") + 4);
  }
  ~RawWebSocket() {
    if (fd_ >= 0) ::close(fd_);
  }
  RawWebSocket(const RawWebSocket&) = delete;
  RawWebSocket& operator=(const RawWebSocket&) = delete;

  bool open() const { return open_; }

  // A client frame's header (FIN set, masked with a zero key, so the payload
  // goes as is) announcing `length` payload bytes.
  void send_header(std::uint8_t opcode, std::uint64_t length) {
    std::string header;
    header += static_cast<char>(0x80 | opcode);
    header += static_cast<char>(0x80 | 127);
    for (int shift = 56; shift >= 0; shift -= 8) {
      header += static_cast<char>((length >> shift) & 0xff);
    }
    header += std::string(4, '\0');
    send_all(header);
  }
  bool send_all(const std::string& bytes) {
    for (std::size_t sent = 0; sent < bytes.size();) {
      const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) return false;
      sent += static_cast<std::size_t>(n);
    }
    return true;
  }

  // Reads frames until the server's close frame; its status code, or nullopt
  // if the connection ended (or the guard ran out) without one.
  std::optional<int> close_code() {
    for (;;) {
      while (buffer_.size() < 2) {
        if (!read_more()) return std::nullopt;
      }
      const auto byte = [this](std::size_t i) { return static_cast<std::uint8_t>(buffer_[i]); };
      std::size_t header = 2;
      std::uint64_t length = byte(1) & 0x7f;
      if (length == 126) header = 4;
      if (length == 127) header = 10;
      while (buffer_.size() < header) {
        if (!read_more()) return std::nullopt;
      }
      if (header > 2) {
        length = 0;
        for (std::size_t i = 2; i < header; ++i) length = length << 8 | byte(i);
      }
      while (buffer_.size() < header + length) {
        if (!read_more()) return std::nullopt;
      }
      if ((byte(0) & 0x0f) == 0x8) {
        if (length < 2) return 1005;  // no status code
        return byte(header) << 8 | byte(header + 1);
      }
      buffer_.erase(0, header + length);
    }
  }

 private:
  bool read_more() {
    std::array<char, 65536> chunk;
    const ssize_t n = ::recv(fd_, chunk.data(), chunk.size(), 0);
    if (n <= 0) return false;
    buffer_.append(chunk.data(), static_cast<std::size_t>(n));
    return true;
  }

  int fd_ = -1;
  bool open_ = false;
  std::string buffer_;
};

TEST(TransportLimits, TextFrameOverTheLimitClosesBeforeItsBytesArrive) {
  TestServer server;  // text limit 1 MiB, uploads 256 MiB
  RawWebSocket socket(server.port());
  ASSERT_TRUE(socket.open());
  // Says 200 MB of text and sends none of it: a server that buffers up to the
  // upload limit waits for the rest and never closes.
  socket.send_header(0x1, 200'000'000);
  EXPECT_EQ(socket.close_code(), 1009);
  EXPECT_TRUE(server.connect()->request(1, "ping").ok());
}

TEST(TransportLimits, TextMessageFramedInPiecesIsClosedOnceItPassesTheLimit) {
  TestServer server;
  RawWebSocket socket(server.port());
  ASSERT_TRUE(socket.open());
  // A first frame (FIN clear) within the limit, then a continuation that
  // promises more than the rest of it.
  std::string first;
  first += static_cast<char>(0x01);
  first += static_cast<char>(0x80 | 126);
  first += static_cast<char>(0x10);  // 4096 bytes
  first += static_cast<char>(0x00);
  first += std::string(4, '\0');
  socket.send_all(first + std::string(4096, ' '));
  socket.send_header(0x0, 100'000'000);
  EXPECT_EQ(socket.close_code(), 1009);
}

TEST(TransportLimits, WholeOversizedTextMessageClosesThatConnectionOnly) {
  TestServer server;
  auto client = server.connect();
  client->send_text(std::string(8 << 20, ' '));
  EXPECT_TRUE(client->wait_closed(kHangGuard));
  // WebSocket++ drops the TCP connection right after its 1009 close frame (a
  // terminal close), with most of this message still unread: the reset that
  // follows can reach a client still sending before it has read that frame,
  // which it then reports as 1006 (CI saw it once in many runs). Which code
  // arrives is the network's race, not the server's choice; the tests above
  // hold the server to 1009 where the client reads before the reset.
  EXPECT_TRUE(client->close_code() == 1009 || client->close_code() == 1006) << client->close_code();
  EXPECT_TRUE(server.connect()->request(1, "ping").ok());
}

TEST(TransportLimits, AnnouncedUploadLargerThanTheTextLimitStillArrives) {
  TestServer server;
  auto client = server.connect();
  // Two megabytes of a text cloud: larger than a text message may be.
  std::string bytes;
  while (bytes.size() < (2u << 20)) bytes += "0.5 0.25 0.125\n";
  Json::Value announce(Json::objectValue);
  announce["name"] = "big.txt";
  announce["size"] = Json::UInt64(bytes.size());
  client->send_request(1, "upload", announce);
  server::FrameHeader header;
  header.kind = server::FrameKind::kUpload;
  header.request_id = 1;
  header.count = bytes.size();
  client->send_binary(server::encode_frame(header, bytes.data(), bytes.size()).message);
  const Reply reply = client->collect(1, kHangGuard);
  EXPECT_TRUE(reply.ok()) << reply.final;
  // The allowance went with the upload: the next long message is refused.
  client->send_binary(server::encode_frame(header, bytes.data(), bytes.size()).message);
  EXPECT_TRUE(client->wait_closed(kHangGuard));
  EXPECT_EQ(client->close_code(), 1009);
}

}  // namespace
}  // namespace occlusion::testing
