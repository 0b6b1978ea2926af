// The keys of -recon (config section occlusion.reconstruct).

#include "occlusion/app/reconstruct_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

const Keys<ReconstructRequest>& reconstruct_keys() {
  using R = ReconstructRequest;
  static const Keys<R> keys = {
      input_key(&R::path,
                "S3DIS room folder (<room>/Annotations/<class>_<k>.txt) or Area_N "
                "folder"),
      cloud_format_key(&R::format, "output format"),
      skip_bad_lines_key(&R::skip_bad_lines),
      out_key(&R::out, "write FOLDER.FMT and FOLDER.recon.json there"),
  };
  return keys;
}

}  // namespace occlusion
