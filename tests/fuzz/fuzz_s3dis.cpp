// S3DIS rooms: the input is a room's Annotations folder, as segments
// separated by a line "--", each a file name line then the file's text, so
// the names (chair_7.TXT, lamp_1.txt, floor.txt) are fuzzed with the contents.

#include <filesystem>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"

namespace {

constexpr std::size_t kMaxFiles = 8;

// A name that stays one entry inside Annotations/ (or "" to drop the file).
std::string plain_name(std::string_view line) {
  std::string name;
  for (const char c : line) {
    if (c != '/' && c != '\0') name += c;
  }
  if (name == "." || name == ".." || name.size() > 200) return "";
  return name;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  namespace fs = std::filesystem;
  const fs::path room = fuzz::scratch_directory() / "office_1";
  std::error_code ignored;
  fs::remove_all(room, ignored);
  fs::create_directories(room / "Annotations");

  std::string_view rest = fuzz::as_text(data, size);
  for (std::size_t files = 0; !rest.empty() && files < kMaxFiles; ++files) {
    std::size_t end = rest.find("\n--\n");
    const std::string_view segment = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 4);
    const std::size_t newline = segment.find('\n');
    const std::string name = plain_name(segment.substr(0, newline));
    if (name.empty()) continue;
    const std::string_view text =
        newline == std::string_view::npos ? std::string_view() : segment.substr(newline + 1);
    fuzz::write_input(text, "office_1/Annotations/" + name);
  }
  fuzz::expect_only<InputError>([&] { read_cloud(room.string()); });
  return 0;
}
