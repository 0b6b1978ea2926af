#pragma once
// The JSON form of a class mapping (analysis/class_mapping.hpp), given to
// -eval with --mapping FILE. Every key is optional:
//
//   {
//     "classes": {"wall": 0, "floor": 1, "ceiling": 1, "chair": 4, ...},
//     "names": {"1": "floor+ceiling"},
//     "ignore": 255,
//     "ignored_classes": ["stairs", "beam"]
//   }
//
// - classes: ground-truth class name -> evaluation id (an integer >= 0).
//   Absent: the base mapping (the built-in one the job's class_mapping key
//   names, table 3.1 by default), its names, ignored classes and ignore id
//   included, so a file can narrow a built-in mapping.
// - names: evaluation id (a decimal string, JSON keys are strings) -> name.
// - ignore: the ignore id, an integer (default 255).
// - ignored_classes: ground-truth classes whose points are skipped.
// docs/metrics.md describes the consequences.

#include <json/value.h>

#include <string>

#include "occlusion/analysis/class_mapping.hpp"

namespace occlusion {

// UsageError naming `where` (the file) and the key for a wrong key, type or
// value, and for a file that cannot be opened or is not JSON: a mapping is
// configuration, like --config.
ClassMapping parse_class_mapping(const Json::Value& root, const std::string& where,
                                 const ClassMapping& base = ClassMapping::seed_table());
ClassMapping load_class_mapping(const std::string& path,
                                const ClassMapping& base = ClassMapping::seed_table());
// Whether the file gives its own "classes" (and so replaces any base).
bool mapping_file_has_classes(const std::string& path);

}  // namespace occlusion
