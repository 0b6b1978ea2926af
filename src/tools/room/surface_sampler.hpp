#pragma once
// Samples surfaces into instances on a jittered grid (one point per cell of
// `spacing` metres, so the density is even without being a lattice), with
// 1 mm of noise along the normal and, optionally, isotropic Gaussian sensor
// noise. A point inside an opening or within 1 cm inside a solid box (a wall
// behind a board, the floor under a bookcase) is left out: no scanner could
// see it.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "occlusion/core/random.hpp"
#include "room_model.hpp"

namespace occlusion::room {

class SurfaceSampler {
 public:
  static constexpr std::size_t kNoBox = std::numeric_limits<std::size_t>::max();

  // sensor_noise: the standard deviation (metres) of the Gaussian noise added
  // to every point; 0 adds none and draws nothing.
  SurfaceSampler(std::uint64_t seed, double spacing, double sensor_noise);

  // Every part's boxes become the solids that hide other surfaces.
  void set_solids(const std::vector<Part>& parts);
  const std::vector<Box>& solids() const { return solids_; }

  // A new instance in `instances`, with its own random stream: changing one
  // object leaves the others' points alone.
  Instance& start(std::vector<Instance>& instances, const std::string& class_name);

  // Uniform per-channel jitter of +-`jitter` around `base`, from the current stream.
  Colour jittered(const Colour& base, int jitter);

  // The parallelogram origin + a u + b v (a, b in [0, 1]); `own_box` (an
  // index into solids(), or kNoBox) does not hide its own faces. Its
  // surface, holes cut out, joins the instance's triangles.
  void rectangle(Instance& instance, const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                 const Eigen::Vector3d& v, const Colour& colour, const std::vector<Box>& holes,
                 std::size_t own_box = kNoBox);

  // The faces of solids()[box] but those in `skipped` (Face bits).
  void box(Instance& instance, std::size_t box, unsigned skipped, const Colour& colour);

  // Every part's boxes in the order set_solids took them, one instance each.
  void parts(std::vector<Instance>& instances, const std::vector<Part>& parts);

 private:
  void add_surface(Instance& instance, const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                   const Eigen::Vector3d& v, const std::vector<Box>& holes) const;
  bool hidden(const Eigen::Vector3d& p, const std::vector<Box>& holes, std::size_t own_box) const;
  Eigen::Vector3d sensor_offset();

  std::uint64_t seed_;
  double spacing_;
  double sensor_noise_;
  Rng rng_{0};
  std::vector<Box> solids_;
};

}  // namespace occlusion::room
