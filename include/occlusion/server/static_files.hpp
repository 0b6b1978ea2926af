#pragma once
// The built viewer over plain HTTP, from the same port as the WebSocket, so a
// user opens one URL. Only GET of files under the web folder; nothing else of
// the file system is reachable.

#include <string>

namespace occlusion::server {

struct HttpResponse {
  int status = 200;
  std::string content_type;
  std::string body;
};

class StaticFiles {
 public:
  // `web_dir` may be empty or lack index.html: then "/" is a page saying how
  // to build the viewer.
  explicit StaticFiles(const std::string& web_dir);

  bool has_viewer() const { return has_viewer_; }
  // `resource` is the request target, e.g. "/assets/index-3f2a.js?v=1".
  HttpResponse get(const std::string& resource) const;

 private:
  std::string root_;  // canonical; empty without a viewer
  bool has_viewer_ = false;
};

// "text/html; charset=utf-8" for .html, ... "application/octet-stream" otherwise.
std::string content_type_for(const std::string& path);

}  // namespace occlusion::server
