#include "occlusion/server/static_files.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace occlusion::server {

namespace fs = std::filesystem;

namespace {

// The viewer's assets are small; a bigger file is not something it asks for.
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{256} << 20;

const char* kNoViewerPage = R"(<!doctype html>
<html><head><meta charset="utf-8"><title>occlusion</title></head>
<body style="font-family: sans-serif; max-width: 40em; margin: 3em auto">
<h1>occlusion server</h1>
<p>The server is running, but it has no viewer to show: <code>--web</code> names no
folder with an <code>index.html</code>.</p>
<p>Build the viewer and restart the server with it:</p>
<pre>cd web &amp;&amp; npm install &amp;&amp; npm run build
occlusion serve --data files --web web/dist</pre>
<p>The WebSocket protocol is open on this port meanwhile (<code>docs/protocol.md</code>).</p>
</body></html>
)";

HttpResponse page(int status, const std::string& text) {
  return {status, "text/plain; charset=utf-8", text + "\n"};
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Percent-decoding of the path part; false for a malformed escape or a NUL.
bool decode_path(const std::string& encoded, std::string& decoded) {
  decoded.clear();
  for (std::size_t i = 0; i < encoded.size(); ++i) {
    if (encoded[i] != '%') {
      decoded += encoded[i];
      continue;
    }
    if (i + 2 >= encoded.size()) return false;
    const int high = hex_value(encoded[i + 1]), low = hex_value(encoded[i + 2]);
    if (high < 0 || low < 0 || (high == 0 && low == 0)) return false;
    decoded += static_cast<char>(high * 16 + low);
    i += 2;
  }
  return true;
}

}  // namespace

std::string content_type_for(const std::string& path) {
  static const std::map<std::string, std::string> kTypes = {
      {".html", "text/html; charset=utf-8"},
      {".htm", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},
      {".map", "application/json"},
      {".svg", "image/svg+xml"},
      {".png", "image/png"},
      {".jpg", "image/jpeg"},
      {".jpeg", "image/jpeg"},
      {".gif", "image/gif"},
      {".ico", "image/x-icon"},
      {".webp", "image/webp"},
      {".wasm", "application/wasm"},
      {".woff", "font/woff"},
      {".woff2", "font/woff2"},
      {".ttf", "font/ttf"},
      {".txt", "text/plain; charset=utf-8"},
  };
  std::string extension = fs::path(path).extension().string();
  for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto it = kTypes.find(extension);
  return it == kTypes.end() ? "application/octet-stream" : it->second;
}

StaticFiles::StaticFiles(const std::string& web_dir) {
  if (web_dir.empty()) return;
  std::error_code error;
  const fs::path root = fs::canonical(web_dir, error);
  if (error || !fs::is_regular_file(root / "index.html", error)) return;
  root_ = root.string();
  has_viewer_ = true;
}

HttpResponse StaticFiles::get(const std::string& resource) const {
  std::string path = resource.substr(0, resource.find_first_of("?#"));
  if (path.empty() || path[0] != '/') return page(400, "bad request");
  if (!has_viewer_) {
    if (path == "/" || path == "/index.html")
      return {200, "text/html; charset=utf-8", kNoViewerPage};
    return page(404, "not found (no viewer is built; see /)");
  }
  std::string decoded;
  if (!decode_path(path, decoded)) return page(400, "bad request");
  if (decoded.back() == '/') decoded += "index.html";

  // Canonical form inside the web folder, symbolic links resolved.
  std::error_code error;
  const fs::path root(root_);
  const fs::path file = fs::weakly_canonical(root / fs::path(decoded).relative_path(), error);
  const auto [root_end, file_end] =
      std::mismatch(root.begin(), root.end(), file.begin(), file.end());
  (void)file_end;
  if (error || root_end != root.end()) return page(403, "forbidden");
  if (!fs::is_regular_file(file, error)) return page(404, "not found");
  if (fs::file_size(file, error) > kMaxFileBytes || error) return page(403, "forbidden");

  std::ifstream in(file, std::ios::binary);
  std::ostringstream body;
  body << in.rdbuf();
  if (!in && !in.eof()) return page(500, "cannot read the file");
  return {200, content_type_for(file.string()), body.str()};
}

}  // namespace occlusion::server
