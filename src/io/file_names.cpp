#include "file_names.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace occlusion::detail {

std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

bool has_suffix(const std::string& path, const std::string& suffix) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (name.size() <= suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), name.rbegin(), [](char expected, char c) {
    return expected == static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  });
}

}  // namespace occlusion::detail
