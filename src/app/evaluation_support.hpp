#pragma once
// Pieces of the evaluate job kept out of its main file (internal to app/):
// reading a scene's two files, and the CSV and Markdown reports.

#include <Eigen/Core>
#include <string>

#include "occlusion/app/evaluate_job.hpp"

namespace occlusion::job {

struct LoadedScene {
  SceneInput input;
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::size_t prediction_non_finite = 0;  // prediction points dropped for NaN or infinity
};

// The built-in mapping for class_mapping ClassMapping::kByGroundTruth: for a
// ground truth labelled with NYU40 classes (a ScanNet scene, or a cloud naming
// them), scannet20, as ScanNet's own evaluate_semantic_label.py scores it,
// with the reason in words; otherwise table3.1, with no reason.
struct BuiltinMappingChoice {
  std::string name;
  std::string reason;
};
BuiltinMappingChoice choose_builtin_mapping(const std::string& name, const PointCloud& cloud);

// A ground truth the mapping can score: labels, class names, and every
// class used mapped. InputError for the first two, UsageError listing the
// unmapped classes.
void check_ground_truth(const std::string& name, const PointCloud& cloud,
                        const ClassMapping& mapping);

// A prediction file: a label file (io/label_file.hpp decides) or a labelled
// cloud. InputError for an unreadable file and a cloud without labels. A cloud
// is read with the ground truth's global shift (`shift`, PointCloud::shift),
// so the two compare point by point in one frame. Points with a non-finite
// coordinate are dropped, as the reader drops them; `non_finite`, when given,
// receives how many.
Prediction load_prediction(const std::string& path, bool skip_bad_lines,
                           const Eigen::Vector3d& shift, std::size_t* non_finite = nullptr);

// The ground truth with read_cloud; the prediction as a label file
// (io/label_file.hpp decides) or a cloud. InputError for unreadable files,
// and for a label file when reading the ground truth dropped points (NaN or
// skipped lines): its labels, given by point order, would no longer line up.
// `class_names_path`, when not empty, names the ground truth's labels.
LoadedScene load_scene(const std::string& ground_truth, const std::string& prediction,
                       bool skip_bad_lines, const std::string& class_names_path);

// What a scene's evaluation should tell the user: ground-truth points left
// without a prediction within max_distance, predicted ids that are no
// evaluation class, a scene with no point in an evaluation class.
void add_scene_warnings(const SceneEvaluation& scene, double max_distance,
                        std::vector<std::string>& warnings);

// One row per class: the sum first (scene "total"), then each scene when
// there are several. Undefined figures are empty fields.
void write_evaluation_csv(const std::string& path, const EvaluateReport& report);
// The per-class table of the sum, and a per-scene summary when there are several.
void write_evaluation_markdown(const std::string& path, const EvaluateReport& report);

}  // namespace occlusion::job
