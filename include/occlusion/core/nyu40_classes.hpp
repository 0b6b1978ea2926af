#pragma once
// The NYU40 classes, the label set ScanNet annotates its meshes with (the
// `label` of scene*_vh_clean_2.labels.ply, the nyu40id / nyu40class columns of
// scannetv2-labels.combined.tsv), and the 20 of them the ScanNet v2 benchmark
// scores. Shared by the ScanNet reader (io) and the built-in scannet20 class
// mapping (analysis), so the names are written once.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion {

// Index = NYU40 id: 0 "unannotated" (ScanNet's label for a vertex no
// annotator labelled), then 1 wall ... 40 otherprop, spelled as ScanNet's
// nyu40class column spells them ("refridgerator", "shower curtain").
const std::vector<std::string>& nyu40_class_names();

// The benchmark's VALID_CLASS_IDS and CLASS_LABELS
// (BenchmarkScripts/3d_evaluation/evaluate_semantic_label.py): the NYU40 ids
// scored, and the names the benchmark prints for them.
struct ScanNetBenchmarkClass {
  std::int32_t nyu40_id;
  const char* name;
};
const std::array<ScanNetBenchmarkClass, 20>& scannet20_classes();

}  // namespace occlusion
