// The keys of `plan` (config section occlusion.plan).

#include <string>

#include "occlusion/analysis/station_candidates.hpp"
#include "occlusion/analysis/station_refinement.hpp"
#include "occlusion/analysis/station_selection.hpp"
#include "occlusion/app/plan_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

namespace {

using R = PlanRequest;

// `stations` and `target_coverage` are the two questions: giving one clears
// the other, so the last source given decides (a config's target, the
// command line's --stations).
Keys<R> question_keys() {
  return {
      custom_key<R>(
          "stations", ValueType::kInteger,
          [](R& r, const Json::Value& v) {
            r.stations = v.asUInt64();
            r.target_coverage = 0.0;
          },
          [](const R& r) {
            return r.stations > 0 ? Json::Value(Json::UInt64(r.stations)) : Json::Value();
          })
          .range(1, 10000)
          .metavar("K")
          .exclusive("question")
          .doc("the best K new stations (instead of target_coverage): greedy is within 1 - 1/e of "
               "the best K, the improvement pass only raises coverage"),
      custom_key<R>(
          "target_coverage", ValueType::kNumber,
          [](R& r, const Json::Value& v) {
            r.target_coverage = v.asDouble();
            r.stations = 0;
          },
          [](const R& r) {
            return r.target_coverage > 0.0 ? Json::Value(r.target_coverage) : Json::Value();
          })
          .range(kLeastTargetCoverage, 1.0)
          .metavar("C")
          .exclusive("question")
          .doc("the fewest new stations that cover this share of the targets' area (instead of "
               "stations); a smaller share than 1e-9 cannot be told from rounding"),
  };
}

// A scanner's limits (analysis/station_visibility.hpp: StationLimits), with
// the up axis the elevations are measured from: the live station
// (`station_view`) takes these same keys.
Keys<R> limit_keys() {
  return {
      key("max_range", &R::max_range)
          .range(0, 1e9)
          .unit("scene units")
          .metavar("D")
          .doc("scanner range: a target farther from a station is not seen by it; 0 = no limit"),
      key("max_incidence", &R::max_incidence)
          .range(0, 90)
          .unit("degrees")
          .metavar("A")
          .doc("a surface met more than this far from its normal is not seen (grazing angles); "
               "0 = no limit"),
      key("min_elevation", &R::min_elevation)
          .range(-90, 90)
          .unit("degrees")
          .metavar("A")
          .doc("scanner's vertical field of view: lowest elevation above the horizontal"),
      key("max_elevation", &R::max_elevation)
          .range(-90, 90)
          .unit("degrees")
          .metavar("A")
          .doc("scanner's vertical field of view: highest elevation above the horizontal"),
      up_key(&R::up),
  };
}

}  // namespace

const Keys<PlanRequest>& plan_limit_keys() {
  static const Keys<R> keys = limit_keys();
  return keys;
}

const Keys<PlanRequest>& plan_keys() {
  static const Keys<R> keys = join<R>({
      {input_key(&R::path,
                 "scene: a mesh (.obj, .ply with faces; targets are -moc's samples) or a point "
                 "cloud in any format of docs/formats.md (targets are its points)")},
      question_keys(),
      {key("improve", &R::improve)
           .doc("after greedy, drop, merge (two into one) and swap stations while the target "
                "holds or coverage rises"),
       key("out_of_reach", &R::out_of_reach)
           .choices({"most", "share"})
           .doc("a target_coverage beyond what all the candidates together see: aim at all of "
                "that (most) or at the target's share of it (share: fewer stations); the report "
                "gives both figures"),
       key("intervisible", &R::intervisible)
           .doc("every station sees the one before it (registration needs overlap); no "
                "approximation guarantee then"),
       key("spacing", &R::spacing)
           .positive_up_to(1e6)
           .unit("scene units")
           .metavar("S")
           .doc("candidates: grid step over the floor plan of the frame (at most " +
                std::to_string(kMaxCandidates) + " positions); auto: about " +
                std::to_string(kAutoGridPositions) + " positions over it, finer in a smaller room"),
       key("refine", &R::refine)
           .doc("move each new station by a local search (a shrinking pattern from half the "
                "spacing, at most " +
                std::to_string(kRefinePositionsPerStation) +
                " positions each, clearance and free space kept) to where it adds the most; not "
                "with intervisible"),
       key("height", &R::height)
           .positive_up_to(1e6)
           .unit("scene units")
           .metavar("H")
           .doc("candidates: scanner height above the floor (the frame's low end along up)"),
       key("clearance", &R::clearance)
           .range(0, 1e6)
           .unit("scene units")
           .metavar("D")
           .doc("candidates: no point or face nearer than this (room for the scanner); they are "
                "also refused inside closed solids and outside the scene"),
       key("candidates", &R::candidates_path)
           .path()
           .metavar("FILE")
           .doc("candidate positions from a cloud file instead of the grid (x y z per line in a "
                ".txt/.xyz, or any cloud format), in the scene's frame; at most " +
                std::to_string(kMaxCandidates) + ", filtered as the grid is"),
       point_list_key("placed", &R::placed)
           .cli("--placed")
           .max_items(10000)
           .doc("a station already there, repeatable: kept and counted first"),
       key("existing_stations", &R::existing_stations)
           .doc("a cloud's own stations (E57 scans, a PCD sensor) count as placed")},
      plan_limit_keys(),
      {key("classes", &R::classes)
           .metavar("A,B,...")
           .doc("count coverage only of these classes (a cloud's labels, a mesh's groups); "
                "empty: everything"),
       primitive_key(&R::primitive), point_radius_key(&R::point_radius),
       disc_coverage_key(&R::disc_coverage), normal_neighbours_key(&R::normal_neighbours),
       self_tolerance_key(&R::self_tolerance), class_names_key(&R::class_names_path),
       skip_bad_lines_key(&R::skip_bad_lines), samples_per_unit_area_key(&R::samples_per_unit_area),
       seed_key(&R::seed), frame_key(&R::frame), threads_key(&R::threads),
       max_memory_key(&R::max_memory_mb), max_work_key(&R::max_work),
       out_key(&R::out,
               "write SCENE.plan.json, SCENE.plan_curve.csv (coverage after each station), "
               "SCENE.plan_candidates.csv (each candidate's coverage alone and gain left) and "
               "SCENE.plan_targets.ply (every target with first_station: the rank of the "
               "first station that sees it, -1 for none)")},
  });
  return keys;
}

}  // namespace occlusion
