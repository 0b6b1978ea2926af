// occlusion: command-line entry point. Maps each job's exceptions to the exit
// codes of the interface contract: 0 success, 2 usage or configuration error,
// 3 input file error, 1 anything else.

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "commands.hpp"
#include "interrupt.hpp"
#include "occlusion/analysis/progress.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/io/input_error.hpp"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInput = 3;

void print_help() {
  std::printf(
      "usage: occlusion COMMAND INPUT [options]\n"
      "\n"
      "How occluded is an indoor scene, seen from given viewpoints?\n"
      "\n"
      "commands:\n"
      "  -moc, mesh-occlusion MESH.obj    visible-area occlusion level of a triangle mesh\n"
      "  -poc, cloud-occlusion CLOUD      occlusion ray ratio of a point cloud, with openings\n"
      "  -rgoc, region-growing-occlusion CLOUD\n"
      "                                   occlusion of a mesh estimated from CLOUD by region "
      "growing\n"
      "  -fscan, scan CLOUD               the points that fixed viewpoints really see\n"
      "  -recon, reconstruct FOLDER       S3DIS room or Area folder -> one labelled cloud\n"
      "  -eval, evaluate GT               segmentation quality (mIoU) of --prediction vs GT\n"
      "  study --config FILE              occlusion against segmentation quality, scene x\n"
      "                                   viewpoint configuration; 'study merge' joins shards\n"
      "  serve                            the browser viewer and its WebSocket server\n"
      "\n"
      "Run 'occlusion COMMAND --help' for a command's options.\n"
      "Exit codes: 0 success, 1 failure, 2 usage or configuration error, 3 input file error.\n");
}

int dispatch(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    print_help();
    return args.empty() ? kExitUsage : kExitOk;
  }
  if (args[0] == "--version") {
    std::printf("occlusion 0.1.0\n");
    return kExitOk;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "-moc" || args[0] == "mesh-occlusion") {
    return occlusion::cli::run_mesh_occlusion_command(rest);
  }
  if (args[0] == "-poc" || args[0] == "cloud-occlusion") {
    return occlusion::cli::run_cloud_occlusion_command(rest);
  }
  if (args[0] == "-rgoc" || args[0] == "region-growing-occlusion") {
    return occlusion::cli::run_region_growing_command(rest);
  }
  if (args[0] == "-fscan" || args[0] == "scan") {
    return occlusion::cli::run_scan_command(rest);
  }
  if (args[0] == "-recon" || args[0] == "reconstruct") {
    return occlusion::cli::run_reconstruct_command(rest);
  }
  if (args[0] == "-eval" || args[0] == "evaluate") {
    return occlusion::cli::run_evaluate_command(rest);
  }
  if (args[0] == "study") return occlusion::cli::run_study_command(rest);
  if (args[0] == "serve") return occlusion::cli::run_serve_command(rest);
  throw occlusion::UsageError("unknown command '" + args[0] + "' (see occlusion --help)");
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    return dispatch(args);
  } catch (const occlusion::UsageError& e) {
    std::fprintf(stderr, "occlusion: %s\n", e.what());
    return kExitUsage;
  } catch (const occlusion::InputError& e) {
    std::fprintf(stderr, "occlusion: %s\n", e.what());
    return kExitInput;
  } catch (const occlusion::Cancelled&) {
    std::fprintf(stderr, "occlusion: cancelled\n");
    // Temporary files are gone by now (the job unwound); die as signalled.
    occlusion::cli::reraise_interrupt();
    return kExitFailure;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "occlusion: out of memory\n");
    return kExitFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "occlusion: %s\n", e.what());
    return kExitFailure;
  }
}
