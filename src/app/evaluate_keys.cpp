// The keys of -eval (config section occlusion.evaluate).

#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

const Keys<EvaluateRequest>& evaluate_keys() {
  using R = EvaluateRequest;
  static const Keys<R> keys = join<R>({
      {key("ground_truth", &R::ground_truth)
           .path()
           .metavar("GT")
           .doc("labelled clouds with class names (PLY/PCD written by occlusion, S3DIS rooms or "
                "Areas, ScanNet scenes, or any labelled cloud with class_names), one per scene"),
       key("predictions", &R::predictions)
           .path()
           .cli("--prediction")
           .alias("--predictions")
           .repeatable()
           .metavar("PRED")
           .doc("the prediction for each ground truth, in the same order: a label file or a "
                "labelled cloud")},
      scoring_keys<R>(true),
      {key("max_distance", &R::max_distance)
           .range(0, 1e6)
           .unit("scene units")
           .metavar("D")
           .doc("a prediction on other points is transferred from its nearest point within D; "
                "0: the points must be the ground truth's"),
       skip_bad_lines_key(&R::skip_bad_lines), class_names_key(&R::class_names_path),
       threads_key(&R::threads),
       out_key(&R::out,
               "write GT.eval.json, .csv (per class) and .md (a table); with several scenes "
               "eval.json, eval.csv, eval.md")},
  });
  return keys;
}

}  // namespace occlusion
