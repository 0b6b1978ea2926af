#pragma once
// Which ground-truth classes are evaluated, and as what. The ground truth
// names its classes (S3DIS: ceiling, floor, wall, ...); a network predicts ids
// of its own label set. The mapping sends each ground-truth class NAME to an
// evaluation id in the network's space; predictions are compared as given.
// Several classes may share an id (the seed's table 3.1 maps floor and
// ceiling to 1: one evaluation class "floor+ceiling").
//
// Ignored ground-truth classes (classes the model cannot predict, S3DIS
// stairs) get the ignore id, which is never an evaluation class, so their
// points are skipped (confusion_matrix.hpp). The JSON form of a mapping is
// read by app/class_mapping_file.hpp; docs/metrics.md describes both.

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "occlusion/analysis/confusion_matrix.hpp"

namespace occlusion {

class ClassMapping {
 public:
  static constexpr std::int32_t kDefaultIgnoreId = 255;
  // The built-in mapping jobs score with when none is named.
  static constexpr const char* kDefaultBuiltin = "table3.1";
  // Not a mapping: a job's request to take the built-in that fits its ground
  // truth's class names (app/evaluate_job.hpp, choose_builtin_mapping).
  static constexpr const char* kByGroundTruth = "auto";

  // ids: ground-truth class name -> evaluation id (>= 0, not ignore_id).
  // names: names of evaluation ids; an id without one is named by its
  //   ground-truth classes, sorted and joined with '+'. A name for an id that
  //   no class in `ids` maps to is an error (a typo would otherwise vanish).
  // ignored: ground-truth classes to skip; they win over `ids`, so a mapping
  //   can be narrowed without rewriting it. An evaluation id all of whose
  //   classes are ignored is no longer an evaluation class.
  // std::invalid_argument for an empty class name, a negative id, an id equal
  // to ignore_id, an empty evaluation name, or no evaluation class left.
  explicit ClassMapping(std::map<std::string, std::int32_t> ids,
                        std::map<std::int32_t, std::string> names = {},
                        std::set<std::string> ignored = {},
                        std::int32_t ignore_id = kDefaultIgnoreId);

  // The seed thesis' table 3.1: wall 0, floor 1, ceiling 1, chair 4, sofa 5,
  // table 6, door 7, window 8, bookcase 9, beam 20, board 21, clutter 25,
  // column 26 (S3DIS names), ignore id 255.
  static ClassMapping seed_table();

  // The ScanNet v2 benchmark's 20 classes over NYU40 ground truth
  // (core/nyu40_classes.hpp): each of the 20 NYU40 classes it scores maps to
  // its NYU40 id (wall 1, floor 2, ..., otherfurniture 39: the ids a benchmark
  // submission predicts), named as the benchmark prints it; the other 20
  // NYU40 classes and "unannotated" are ignored, as the benchmark skips every
  // ground truth outside VALID_CLASS_IDS. Ignore id 255.
  static ClassMapping scannet20();

  // The built-in mappings by name: "table3.1" (seed_table) and "scannet20";
  // nothing for another name.
  static std::optional<ClassMapping> builtin(const std::string& name);
  static const std::vector<std::string>& builtin_names();

  // The same mapping with more ignored classes.
  ClassMapping with_ignored(const std::vector<std::string>& classes) const;

  // Sorted by id; what ConfusionMatrix is built over.
  const std::vector<EvaluationClass>& evaluation_classes() const { return classes_; }
  // As given, ignored classes included.
  const std::map<std::string, std::int32_t>& ids() const { return ids_; }
  const std::set<std::string>& ignored() const { return ignored_; }
  std::int32_t ignore_id() const { return ignore_id_; }

  // A ground-truth class's evaluation id: ignore_id() when ignored, nothing
  // when the mapping does not know it.
  std::optional<std::int32_t> find(const std::string& class_name) const;

  // Names of the classes that points use (labels index class_names; -1 is
  // no class) and the mapping does not know, sorted.
  std::vector<std::string> unmapped_classes(const std::vector<std::int32_t>& labels,
                                            const std::vector<std::string>& class_names) const;
  // Each label as an evaluation id; -1 (unlabelled ground truth) becomes the
  // ignore id. std::invalid_argument listing unmapped classes, or for a label
  // without a name.
  std::vector<std::int32_t> map_labels(const std::vector<std::int32_t>& labels,
                                       const std::vector<std::string>& class_names) const;

 private:
  std::map<std::string, std::int32_t> ids_;
  std::map<std::int32_t, std::string> names_;
  std::set<std::string> ignored_;
  std::int32_t ignore_id_ = kDefaultIgnoreId;
  std::vector<EvaluationClass> classes_;
};

}  // namespace occlusion
