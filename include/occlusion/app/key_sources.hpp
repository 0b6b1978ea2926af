#pragma once
// Where key values come from: a config file's section, command-line
// arguments, a server request's params, Python keyword arguments. Each face
// turns its input into a KeySource (checked against the declarations as it is
// built, so errors name the key as that face spells it); apply_sources() then
// fills a request from the sources in order, later ones overriding earlier
// ones (the command line overrides the config file).

#include <json/value.h>

#include <functional>
#include <string>
#include <vector>

#include "occlusion/app/key.hpp"

namespace occlusion {

enum class Face { kCli, kConfig, kServer, kPython };

struct KeyValue {
  std::string key;  // config name
  Json::Value value;
  std::string spelling;  // as the user wrote it: "--point-radius", "'occlusion.mesh.pattern'"
};

struct KeySource {
  Face face = Face::kCli;
  std::string prefix;   // before every message: "study.json: " for a config file
  std::string section;  // the config section, for spelling keys the user did not give
  std::vector<KeyValue> values;

  const KeyValue* find(const std::string& key) const;
};

// How a face spells a key it did not receive (for errors of cross-key checks).
std::string face_spelling(Face face, const KeyInfo& info, const std::string& section);

// Path keys: relative paths are resolved by the face (a config file's folder,
// the server's data directory). `output`: the path is written, need not exist.
using PathResolver = std::function<std::string(const std::string& path, bool output)>;

// A JSON object of key values (a config section, request params, kwargs).
// Unknown key, wrong type or out-of-range value: UsageError naming it.
KeySource source_from_json(const Json::Value& object, const std::vector<KeyInfo>& infos, Face face,
                           const std::string& prefix, const std::string& section,
                           const PathResolver& resolve = {});

// Command-line options: `--key VALUE`, `--key=VALUE`; a bool key alone is
// true (`--exterior`), or takes true/false after it; a repeatable key adds an
// item each time; other lists are comma-separated. Arguments that are not
// options fill `positional_key` (a list: one item each; otherwise one only).
// `command` names the command in messages.
KeySource source_from_arguments(const std::vector<std::string>& args,
                                const std::vector<KeyInfo>& infos, const std::string& command,
                                const std::string& positional_key);

// Fills `request` from the sources, in order. The values were checked when the
// sources were built.
template <class R>
void apply_sources(const Keys<R>& keys, const std::vector<KeySource>& sources, R& request);

// A KeyError re-spelled as the user wrote the key (or as their face spells it).
UsageError respelled(const KeyError& error, const std::vector<KeySource>& sources,
                     const std::vector<KeyInfo>& infos);

// Implementation detail of apply_sources: the exclusive groups and implied
// keys of one source, checked and expanded. Throws UsageError.
std::vector<KeyValue> expanded(const KeySource& source, const std::vector<KeyInfo>& infos);

template <class R>
void apply_sources(const Keys<R>& keys, const std::vector<KeySource>& sources, R& request) {
  const std::vector<KeyInfo> infos = key_infos(keys);
  for (const KeySource& source : sources) {
    for (const KeyValue& value : expanded(source, infos)) {
      for (const auto& k : keys) {
        if (k.info.name == value.key) k.set(request, value.value);
      }
    }
  }
}

}  // namespace occlusion
