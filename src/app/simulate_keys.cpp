// The keys of simulate (config section occlusion.simulate).

#include "occlusion/app/sensor_model_keys.hpp"
#include "occlusion/app/shared_keys.hpp"
#include "occlusion/app/simulate_job.hpp"

namespace occlusion {

const Keys<SimulateRequest>& simulate_keys() {
  using R = SimulateRequest;
  static const Keys<R> keys = join<R>({
      {input_key(&R::path,
                 "mesh to scan: .obj or .ply with faces; its groups name the points' classes "
                 "(chair_3: class chair, one instance per group)"),
       key("sensor", &R::sensor)
           .choices({"laser", "camera"})
           .doc("laser: a terrestrial laser scanner's angular grid and range noise; camera: a "
                "depth camera's pinhole, depth noise and disparity steps"),
       point_list_key("stations", &R::stations)
           .cli("--station")
           .max_items(10000)
           .doc("where the sensor stands, repeatable; none: the centre of the mesh's box"),
       point_list_key("look_at", &R::look_at)
           .max_items(10000)
           .doc("camera: the point each station's camera looks at, one per station, in order"),
       up_key(&R::up).doc("the laser's vertical axis and the camera image's up"),
       key("noise", &R::noise)
           .doc("measurement noise and depth steps; false: every return exactly on the mesh"),
       max_incidence_key(&R::max_incidence), seed_key(&R::seed),
       key("truth", &R::truth)
           .doc("also write each point's true surface point (true_x, true_y, true_z), its "
                "face's normal towards the station (true_normal_x, _y, _z) and face")},
      {key("colour_from", &R::colour_from)
           .path()
           .metavar("CLOUD")
           .doc("a coloured cloud of the same scene, in the mesh's frame (the room's points "
                "beside generate_s3dis_room --mesh's OBJ): each return takes the colour of its "
                "nearest point, as a scanner's camera colours its returns")},
      mount(laser_scanner_keys(), &R::laser),
      mount(depth_camera_keys(), &R::camera),
      {cloud_format_key(&R::format, "format of the written cloud"), threads_key(&R::threads),
       max_memory_key(&R::max_memory_mb),
       out_key(&R::out,
               "write MESH.sim.FMT (the scan: labels, instances, stations and each point's "
               "station) and MESH.sim.json")},
  });
  return keys;
}

}  // namespace occlusion
