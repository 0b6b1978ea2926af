#pragma once
// Loaded scenes kept for the next client that asks for the same file: keyed by
// path, modification times and sizes (a file changed on disk is a new key),
// least recently used evicted first, within a byte bound. Thread-safe: the
// workers that load scenes share one cache.

#include <cstddef>
#include <filesystem>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "loaded_scene.hpp"

namespace occlusion::server {

class SceneCache {
 public:
  explicit SceneCache(std::size_t max_bytes) : max_bytes_(max_bytes) {}

  std::shared_ptr<const LoadedScene> find(const std::string& key);
  // A scene larger than the bound is not kept.
  void insert(const std::string& key, std::shared_ptr<const LoadedScene> scene);

  std::size_t bytes() const;
  std::size_t size() const;

 private:
  struct Entry {
    std::string key;
    std::shared_ptr<const LoadedScene> scene;
    std::size_t bytes = 0;
  };
  void evict_locked();

  mutable std::mutex mutex_;
  std::size_t max_bytes_;
  std::size_t bytes_ = 0;
  std::list<Entry> entries_;  // most recently used first
  std::map<std::string, std::list<Entry>::iterator> index_;
};

// The cache key of a file or folder (S3DIS rooms are folders: every file below
// takes part, so editing one annotation file invalidates the room). `variant`
// distinguishes reads of one file with different options.
std::string scene_key(const std::filesystem::path& path, const std::string& variant);

}  // namespace occlusion::server
