// The server's binary messages (uploads): the header is decoded and checked
// before anything else looks at the payload. A bad frame is a ProtocolError.

#include "fuzz_support.hpp"
#include "occlusion/server/binary_frame.hpp"
#include "occlusion/server/protocol_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion::server;
  occlusion::fuzz::expect_only<ProtocolError>([&] {
    const FrameHeader header = decode_frame_header(occlusion::fuzz::as_text(data, size));
    describe(header);
    // What decode accepted re-encodes to a frame that decodes the same
    // (reserved header bytes aside).
    const Frame again = encode_frame(header, data + kFrameHeaderSize, header.payload_bytes());
    const FrameHeader back = decode_frame_header(again.message);
    if (back.kind != header.kind || back.request_id != header.request_id ||
        back.type != header.type || back.components != header.components ||
        back.count != header.count || back.item != header.item ||
        again.message.substr(kFrameHeaderSize) !=
            occlusion::fuzz::as_text(data, size).substr(kFrameHeaderSize)) {
      std::fprintf(stderr, "fuzz: frame does not survive re-encoding\n");
      std::abort();
    }
  });
  return 0;
}
