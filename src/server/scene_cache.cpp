#include "scene_cache.hpp"

#include <system_error>

#include "occlusion/io/input_error.hpp"
#include "occlusion/io/scene_project.hpp"

namespace occlusion::server {

namespace fs = std::filesystem;

std::shared_ptr<const LoadedScene> SceneCache::find(const std::string& key) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto it = index_.find(key);
  if (it == index_.end()) return nullptr;
  entries_.splice(entries_.begin(), entries_, it->second);
  return it->second->scene;
}

void SceneCache::insert(const std::string& key, std::shared_ptr<const LoadedScene> scene) {
  const std::size_t size = scene->bytes();
  const std::lock_guard<std::mutex> lock(mutex_);
  if (const auto it = index_.find(key); it != index_.end()) {
    bytes_ -= it->second->bytes;
    entries_.erase(it->second);
    index_.erase(it);
  }
  if (size > max_bytes_) return;
  entries_.push_front(Entry{key, std::move(scene), size});
  index_[key] = entries_.begin();
  bytes_ += size;
  evict_locked();
}

void SceneCache::evict_locked() {
  while (bytes_ > max_bytes_ && !entries_.empty()) {
    bytes_ -= entries_.back().bytes;
    index_.erase(entries_.back().key);
    entries_.pop_back();
  }
}

std::size_t SceneCache::bytes() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return bytes_;
}

std::size_t SceneCache::size() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

std::string scene_key(const fs::path& path, const std::string& variant) {
  std::string key = path.string() + '\n' + variant;
  const auto stamp = [&key](const fs::path& file) {
    std::error_code error;
    const auto size = fs::is_regular_file(file, error) ? fs::file_size(file, error) : 0;
    const auto time = fs::last_write_time(file, error).time_since_epoch().count();
    key += '\n' + file.string() + ' ' + std::to_string(size) + ' ' + std::to_string(time);
  };
  stamp(path);
  // A project is its scans and pose files too: a scan rewritten under an
  // unchanged project is a new scene. A project that does not parse is
  // refused by the load that follows, with the reason.
  if (is_project_file(path.string())) {
    try {
      for (const SceneScan& scan : read_project_file(path.string())) {
        stamp(scan.path);
        if (!scan.pose_path.empty()) stamp(scan.pose_path);
      }
    } catch (const InputError&) {
    }
  }
  std::error_code error;
  if (fs::is_directory(path, error)) {
    for (fs::recursive_directory_iterator it(path, error), end; !error && it != end;
         it.increment(error)) {
      stamp(it->path());
    }
  }
  return key;
}

}  // namespace occlusion::server
