#pragma once
// The `simulate` job: a mesh scanned by a virtual terrestrial laser scanner
// or depth camera (analysis/virtual_scanner.hpp), written as the sensor's
// cloud with its stations, labels from the mesh's groups and, on request, each
// return's truth.

#include <json/value.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/analysis/virtual_scanner.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {

struct SimulateRequest {
  std::string path;
  std::string sensor = "laser";  // laser or camera
  // Where the sensor stands, in the mesh's frame; empty: one station at the
  // centre of the mesh's box.
  std::vector<Eigen::Vector3d> stations;
  // Cameras only: the point each station's camera looks at (one per station).
  std::vector<Eigen::Vector3d> look_at;
  std::string up = "+z";  // the laser's vertical axis, the camera image's up
  LaserScannerModel laser;
  DepthCameraModel camera;
  bool noise = true;
  double max_incidence = SimulationOptions{}.max_incidence_deg;
  std::uint64_t seed = 1;
  bool truth = false;  // write each return's true point, normal and face
  // A coloured cloud of the same scene: each return takes the colour of its
  // nearest point, as a scanner's camera colours its returns; "": none.
  std::string colour_from;
  std::string format = "ply";  // of the written cloud: ply or pcd
  unsigned threads = 0;
  std::string out;
  std::uint64_t max_memory_mb = 0;
};

struct SimulateReport {
  SimulateRequest request;
  SimulatedScan scan;
  std::vector<ScannerStation> stations;  // in the mesh's frame, as scanned
  std::string station_source;            // "stations" or "the centre of the mesh's box"
  std::size_t degenerate_faces_skipped = 0;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double load_seconds = 0.0;
  double total_seconds = 0.0;
};

void validate(const SimulateRequest& request);
// Every key of the job (config section occlusion.simulate), declared once.
const Keys<SimulateRequest>& simulate_keys();
SimulateReport run_simulate(const SimulateRequest& request, const Progress& progress = {});
// The same on a mesh in memory (Python's arrays); nothing is written, and
// nothing read but colour_from's cloud.
SimulateReport run_simulate_on(const TriangleMesh& mesh, const SimulateRequest& request,
                               const Progress& progress = {});
// The truth as extra per-point fields (true_x .. true_normal_z, face), for writers.
std::vector<ScalarField> truth_fields(const SimulatedScan& scan);
// Headline: points.
Json::Value to_json(const SimulateReport& report);

}  // namespace occlusion
