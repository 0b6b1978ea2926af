// The point model a cloud job traces with (job_support.hpp), and the warnings
// that go with a setting that makes its answers wrong.
//
// How open a surface a model leaves: on a surface sampled at random with
// density rho, the median nearest-neighbour distance s satisfies
// pi rho s^2 = ln 2, and discs of radius r (or spheres, whose cut through the
// surface is such a disc) leave exp(-rho pi r^2) = 2^-(r/s)^2 of it open.

#include <cmath>
#include <sstream>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"

namespace occlusion::job {

namespace {

// Above these open shares a warning says what leaks.
constexpr double kSphereOpenWarning = 0.05;
constexpr double kDiscOpenWarning = 0.01;
// Above this share of points traced as spheres, the disc model is weak.
constexpr double kUnorientedWarning = 0.3;

double open_share(double radius, double spacing) {
  if (!(spacing > 0.0)) return 0.0;
  return std::exp2(-(radius / spacing) * (radius / spacing));
}

std::string percent(double share) {
  std::ostringstream text;
  text.precision(share < 0.1 ? 2 : 3);
  text << 100.0 * share << " %";
  return text.str();
}

// Spheres wider than the gaps between points hide the neighbours of a point
// on a surface seen at a grazing angle (scan.hpp: below asin(r / tolerance)),
// and from a sensor the rays to neighbouring pixels (README, Point model).
void warn_hiding_spheres(const PointModelReport& model, std::vector<std::string>& warnings) {
  const double spacing = model.radius.spacing.spacing;
  if (!(model.radius.radius > kHighRadiusPerSpacing * spacing)) return;
  std::ostringstream message;
  message << "spheres of radius " << model.radius.radius << " are " << model.radius.radius / spacing
          << " x the point spacing " << spacing
          << " (median nearest-neighbour distance): neighbouring points hide each other, so "
             "the visible fraction is too low; primitive disc (the default) closes surfaces "
             "without hiding them";
  warnings.push_back(message.str());
}

void warn_open_surfaces(const PointModelReport& model, const std::string& job,
                        std::vector<std::string>& warnings) {
  const double spacing = model.radius.spacing.spacing;
  const double open = open_share(model.radius.radius, spacing);
  const bool sphere = model.primitive == "sphere";
  if (sphere && job == "-fscan") warn_hiding_spheres(model, warnings);
  if (open <= (sphere ? kSphereOpenWarning : kDiscOpenWarning)) return;
  std::ostringstream message;
  message << model.primitive << "s of radius " << model.radius.radius
          << (model.radius.automatic ? " (auto)" : "") << " leave about " << percent(open)
          << " of a surface sampled at random at this cloud's spacing " << spacing
          << " (median nearest-neighbour distance) open: "
          << (job == "-fscan"
                  ? "rays pass between the points of a surface, so points behind it count as "
                    "seen and the visible fraction is too high"
                  : "rays leak through surfaces, so the occlusion level is too high")
          << "; "
          << (sphere ? "primitive disc (the default) closes surfaces without hiding them"
                     : "omit point_radius for discs sized from their neighbours");
  warnings.push_back(message.str());
}

}  // namespace

PointModel choose_point_model(const PointCloud& cloud, const PointSettings& settings,
                              const std::string& job, std::vector<std::string>& warnings,
                              const Progress& progress) {
  PointModel model;
  PointModelReport& report = model.report;
  report.primitive = settings.primitive;
  if (settings.primitive == "sphere") {
    report.radius =
        choose_point_radius(cloud, settings.point_radius, job, std::nullopt, settings.threads);
    warn_open_surfaces(report, job, warnings);
    return model;
  }
  if (settings.primitive != "disc") {
    throw KeyError("primitive", "must be disc or sphere, got '" + settings.primitive + "'");
  }
  SurfelOptions options;
  options.neighbours = settings.normal_neighbours;
  options.coverage = settings.disc_coverage;
  options.fixed_radius = is_auto_radius(settings.point_radius) ? 0.0 : settings.point_radius;
  options.threads = settings.threads;
  options.keep_thickness = job != "-poc";
  try {
    model.surfels = estimate_surfels(cloud, options, progress);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("primitive disc: ") + e.what() +
                     "; trace spheres of a given radius instead (primitive sphere)");
  }
  // The spacing from the discs' own search, when it measured it.
  report.radius = choose_point_radius(cloud, settings.point_radius, job, model.surfels->spacing,
                                      settings.threads);
  const SurfelStats& stats = model.surfels->stats;
  report.surfels = stats;
  report.noise = model.surfels->noise.stations;
  if (options.keep_thickness) {
    report.carving = model.surfels->carving;
    for (const SightLineCarving::UncarvedStation& station : report.carving->implausible) {
      std::ostringstream message;
      const std::string name = station.name.empty() ? std::string("(unnamed)") : station.name;
      if (station.beam_order) {
        message << percent(station.by_others_share) << " of the lines of sight from station "
                << name << " to the points it recorded cross other stations' scans (more than "
                << percent(kMaxBlockedShare)
                << "): its pose among them is probably wrong (register the scans: occlusion "
                   "register); its lines of sight were not carved (README, Point model)";
      } else {
        message << "the model hides " << percent(station.blocked_share) << " of the points station "
                << name << " recorded from that station itself (more than "
                << percent(kMaxBlockedShare)
                << "): its pose is probably not where they were measured from, or its noise "
                   "exceeds the model's bands; its lines of sight were not carved (README, "
                   "Point model)";
      }
      warnings.push_back(message.str());
    }
  }
  report.normal_neighbours = settings.normal_neighbours;
  if (report.radius.automatic) {
    report.disc_coverage = settings.disc_coverage;
    report.radius.radius = stats.radius_median;
  } else {
    warn_open_surfaces(report, job, warnings);
  }
  const double unoriented =
      static_cast<double>(stats.unoriented) / static_cast<double>(stats.points);
  if (unoriented > kUnorientedWarning) {
    std::ostringstream message;
    message << percent(unoriented) << " of the points (" << stats.unoriented
            << ") have no plane their " << settings.normal_neighbours
            << " nearest neighbours agree on (edges, clutter, lines of points, stray points) and "
               "are traced as spheres of their disc's radius, which hide what lies just behind "
               "them at grazing angles; a denser cloud, or more normal_neighbours, gives more "
               "of them a plane";
    warnings.push_back(message.str());
  }
  return model;
}

Json::Value point_model_json(const PointModelReport& model) {
  Json::Value json(Json::objectValue);
  json["primitive"] = model.primitive;
  json["point_radius"] = model.radius.radius;
  json["point_radius_auto"] = model.radius.automatic;
  if (model.surfels) {
    const SurfelStats& s = *model.surfels;
    if (model.radius.automatic) json["disc_coverage"] = model.disc_coverage;
    json["normal_neighbours"] = model.normal_neighbours;
    json["discs"] = Json::UInt64(s.oriented);
    json["spheres"] = Json::UInt64(s.unoriented);
    json["stray_points"] = Json::UInt64(s.stray);
    json["duplicate_points"] = Json::UInt64(s.duplicates);
    json["radius_quantile_10"] = s.radius_quantile_10;
    json["radius_median"] = s.radius_median;
    json["radius_quantile_90"] = s.radius_quantile_90;
    json["surface_variation_median"] = s.surface_variation_median;
    json["thickness_median"] = s.thickness_median;
    json["discs_facing_station"] = Json::UInt64(s.facing_station);
  }
  if (model.carving) {
    // Lines of sight from each point's own station (sight_line_carving.hpp).
    Json::Value carving(Json::objectValue);
    carving["lines"] = Json::UInt64(model.carving->lines);
    carving["blocked"] = Json::UInt64(model.carving->blocked);
    carving["discs_shrunk"] = Json::UInt64(model.carving->shrunk);
    carving["still_blocked"] = Json::UInt64(model.carving->still_blocked);
    Json::Value uncarved(Json::arrayValue);
    for (const SightLineCarving::UncarvedStation& station : model.carving->implausible) {
      Json::Value entry(Json::objectValue);
      entry["station"] = station.name;
      entry["blocked_share"] = station.blocked_share;
      entry["beam_order"] = station.beam_order;
      entry["blocked_by_other_stations_share"] = station.by_others_share;
      uncarved.append(entry);
    }
    carving["uncarved_stations"] = uncarved;
    json["sight_line_carving"] = carving;
  }
  if (!model.noise.empty()) {
    // Per station, per range bin: [range from, range to, points, sigma].
    Json::Value noise(Json::objectValue);
    noise["band_sigmas"] = kBandSigmas;
    Json::Value stations(Json::arrayValue);
    for (const StationNoise& station : model.noise) {
      Json::Value entry(Json::objectValue);
      entry["station"] = station.station.empty() ? Json::Value() : Json::Value(station.station);
      Json::Value bins(Json::arrayValue);
      for (const NoiseBin& bin : station.bins) {
        Json::Value row(Json::arrayValue);
        row.append(bin.range_lo);
        row.append(bin.range_hi);
        row.append(Json::UInt64(bin.points));
        row.append(bin.sigma);
        bins.append(row);
      }
      entry["bins"] = bins;
      // Stored as its beams swept (analysis/beam_order.hpp): its noise read
      // from consecutive returns too, its position checked, its step.
      entry["beam_order"] = station.beam_order;
      entry["beam_step_degrees"] =
          station.beam_order ? Json::Value(station.beam_step * 180.0 / M_PI) : Json::Value();
      stations.append(entry);
    }
    noise["stations"] = stations;
    json["surface_noise"] = noise;
  }
  json["open_surface_share"] =
      model.open_surface_share ? Json::Value(*model.open_surface_share) : Json::Value();
  return json;
}

}  // namespace occlusion::job
