// Readers and writers for every format io/ knows (docs/formats.md), numpy in
// and out. Arrays read from files are the library's own buffers, handed over
// without a copy.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "numpy_views.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/csv_file.hpp"
#include "occlusion/io/label_file.hpp"
#include "occlusion/io/obj_reader.hpp"
#include "occlusion/io/obj_writer.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"
#include "occlusion/io/polygon_file.hpp"
#include "station_values.hpp"

namespace py = pybind11;

namespace occlusion::python {
namespace {

// A cloud as Python sees it: numpy arrays (None for an attribute the file
// lacks) plus what the reader reports.
struct CloudArrays {
  py::array positions;            // float32 (N, 3), relative to shift
  std::array<double, 3> shift{};  // the global shift (PointCloud::shift)
  py::object colours;             // uint8 (N, 3) or None
  py::object labels;              // int32 (N,) or None; -1 = unlabelled
  py::object instances;           // int32 (N,) or None
  py::object intensities;         // float32 (N,) or None
  py::object station_ids;         // int32 (N,) or None: index into stations
  py::list stations;              // stations_to_python
  py::object sensor;              // sensor_to_python: a single-view frame's camera, or None
  py::object pixels;              // uint32 (N,) or None: each point's pixel in the sensor's grid
  std::vector<std::string> class_names;
  py::dict fields;  // other per-point properties: name -> float32 or int32 (N,)
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> rooms;
  std::vector<std::string> warnings;  // CloudReadReport::warnings
};

struct MeshArrays {
  py::array vertices;    // float64 (V, 3)
  py::array faces;       // uint32 (M, 3)
  py::array face_group;  // uint32 (M,)
  std::vector<std::string> group_names;
  std::size_t degenerate_faces = 0;  // skipped by the reader (mesh_read_report.hpp)
};

py::object optional_array(py::array array, bool present) {
  return present ? py::object(std::move(array)) : py::object(py::none());
}

// A cloud in memory as Python's Cloud; `report` adds what reading said
// (extra fields, dropped points, rooms).
CloudArrays make_cloud_arrays(PointCloud cloud, CloudReadReport report) {
  CloudArrays out;
  out.shift = {cloud.shift.x(), cloud.shift.y(), cloud.shift.z()};
  out.positions = to_numpy<float>(std::move(cloud.positions));
  const bool has_colours = cloud.has_colours(), has_labels = cloud.has_labels(),
             has_instances = cloud.has_instances();
  out.colours = optional_array(to_numpy<std::uint8_t>(std::move(cloud.colours)), has_colours);
  out.labels = optional_array(to_numpy<std::int32_t>(std::move(cloud.labels)), has_labels);
  out.instances = optional_array(to_numpy<std::int32_t>(std::move(cloud.instances)), has_instances);
  const bool has_intensities = cloud.has_intensities(), has_station_ids = cloud.has_station_ids();
  out.intensities = optional_array(to_numpy<float>(std::move(cloud.intensities)), has_intensities);
  out.station_ids =
      optional_array(to_numpy<std::int32_t>(std::move(cloud.station_ids)), has_station_ids);
  out.stations = stations_to_python(cloud.stations);
  out.sensor = sensor_to_python(cloud.sensor);
  const bool has_pixels = cloud.has_pixels();
  out.pixels = optional_array(to_numpy<std::uint32_t>(std::move(cloud.pixels)), has_pixels);
  out.class_names = std::move(cloud.class_names);
  for (ScalarField& field : report.extra_fields) {
    if (field.integer) {
      std::vector<std::int32_t> whole(field.values.begin(), field.values.end());
      out.fields[py::str(field.name)] = to_numpy<std::int32_t>(std::move(whole));
    } else {
      out.fields[py::str(field.name)] = to_numpy<float>(std::move(field.values));
    }
  }
  out.dropped_nan = report.dropped_nan;
  out.skipped_lines = report.skipped_lines;
  out.rooms = std::move(report.rooms);
  out.warnings = std::move(report.warnings);
  return out;
}

CloudArrays read_cloud_arrays(const std::string& path, bool skip_bad_lines) {
  CloudReadOptions options;
  options.skip_bad_lines = skip_bad_lines;
  CloudReadReport report;
  PointCloud cloud;
  {
    py::gil_scoped_release release;
    cloud = read_cloud(path, options, &report);
  }
  return make_cloud_arrays(std::move(cloud), std::move(report));
}

std::optional<CloudFormat> cloud_format(const std::optional<std::string>& name) {
  static const std::map<std::string, CloudFormat> kFormats = {
      {"pcd_binary_compressed", CloudFormat::kPcdBinaryCompressed},
      {"pcd_binary", CloudFormat::kPcdBinary},
      {"pcd_ascii", CloudFormat::kPcdAscii},
      {"ply_binary", CloudFormat::kPlyBinary},
      {"ply_ascii", CloudFormat::kPlyAscii}};
  if (!name) return std::nullopt;
  const auto found = kFormats.find(*name);
  if (found == kFormats.end()) {
    throw py::value_error("format: '" + *name +
                          "' is none of pcd_binary_compressed, pcd_binary, pcd_ascii, "
                          "ply_binary, ply_ascii");
  }
  return found->second;
}

std::vector<ScalarField> scalar_fields(const py::dict& fields) {
  std::vector<ScalarField> out;
  for (const auto& item : fields) {
    ScalarField field;
    field.name = item.first.cast<std::string>();
    const py::array values = py::array::ensure(item.second);
    if (!values || values.ndim() != 1) {
      throw py::value_error("fields['" + field.name + "']: expected a 1-D array");
    }
    const char kind = values.dtype().kind();
    field.integer = kind == 'i' || kind == 'u' || kind == 'b';
    const auto as_float = py::array_t<float, py::array::forcecast>::ensure(values);
    if (!as_float) throw py::value_error("fields['" + field.name + "']: expected numbers");
    field.values.assign(as_float.data(), as_float.data() + as_float.size());
    out.push_back(std::move(field));
  }
  return out;
}

void write_cloud_arrays(const std::string& path, const py::handle& positions,
                        const py::handle& colours, const py::handle& labels,
                        const py::handle& instances,
                        const std::optional<std::vector<std::string>>& class_names,
                        const py::handle& intensities, const py::handle& station_ids,
                        const py::handle& stations, const py::dict& fields,
                        const std::optional<std::string>& format,
                        const std::array<double, 3>& shift) {
  PointCloud cloud;
  cloud.positions = points_from_array(positions, "positions");
  cloud.shift = Eigen::Vector3d(shift[0], shift[1], shift[2]);
  if (!colours.is_none()) cloud.colours = colours_from_array(colours, "colours");
  if (!labels.is_none()) cloud.labels = int32_from_array(labels, "labels");
  if (!instances.is_none()) cloud.instances = int32_from_array(instances, "instances");
  if (class_names) cloud.class_names = *class_names;
  if (!intensities.is_none()) cloud.intensities = float32_from_array(intensities, "intensities");
  if (!station_ids.is_none()) cloud.station_ids = int32_from_array(station_ids, "station_ids");
  if (!stations.is_none()) cloud.stations = stations_from_python(stations, "stations");
  const std::vector<ScalarField> extra = scalar_fields(fields);
  const std::optional<CloudFormat> chosen = cloud_format(format);
  py::gil_scoped_release release;
  write_cloud(path, cloud, extra, chosen);
}

MeshArrays read_mesh_arrays(const std::string& path) {
  TriangleMesh mesh;
  MeshReadReport report;
  {
    py::gil_scoped_release release;
    mesh = read_obj(path, &report);
  }
  MeshArrays out;
  out.degenerate_faces = report.degenerate_faces;
  out.vertices = to_numpy<double>(std::move(mesh.vertices));
  out.faces = to_numpy<std::uint32_t>(std::move(mesh.faces));
  out.face_group = to_numpy<std::uint32_t>(std::move(mesh.face_group));
  out.group_names = std::move(mesh.group_names);
  return out;
}

std::vector<float> face_values_from_array(const py::handle& object, std::size_t faces) {
  const auto values = py::array_t<float, py::array::forcecast>::ensure(object);
  if (!values || values.ndim() != 1 || static_cast<std::size_t>(values.size()) != faces) {
    throw py::value_error("face_values: expected shape (" + std::to_string(faces) + ",)");
  }
  return std::vector<float>(values.data(), values.data() + values.size());
}

std::vector<std::vector<Eigen::Vector3d>> polygons_from_list(const py::list& polygons) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const Vec3View view(polygons[p], "polygons[" + std::to_string(p) + "]");
    std::vector<Eigen::Vector3d> points(view.size());
    for (std::size_t i = 0; i < view.size(); ++i) points[i] = view.point_d(i);
    out.push_back(std::move(points));
  }
  return out;
}

}  // namespace

py::object cloud_object(PointCloud cloud, std::vector<ScalarField> fields) {
  CloudReadReport report;
  report.extra_fields = std::move(fields);
  return py::cast(make_cloud_arrays(std::move(cloud), std::move(report)));
}

void bind_io(py::module_& m) {
  py::class_<CloudArrays>(m, "Cloud", "A point cloud read by read_cloud.")
      .def_readonly("positions", &CloudArrays::positions,
                    "float32 (N, 3), relative to shift: a point in the file is position + shift")
      .def_readonly("shift", &CloudArrays::shift,
                    "The global shift (x, y, z) subtracted from clouds far from the origin, "
                    "else zeros; jobs take viewpoints and openings in the file's frame")
      .def_readonly("colours", &CloudArrays::colours, "uint8 (N, 3) RGB, or None")
      .def_readonly("labels", &CloudArrays::labels,
                    "int32 (N,) semantic class ids (-1 = unlabelled), or None")
      .def_readonly("instances", &CloudArrays::instances, "int32 (N,) instance ids, or None")
      .def_readonly("intensities", &CloudArrays::intensities,
                    "float32 (N,) return strengths as the file stores them, or None")
      .def_readonly("station_ids", &CloudArrays::station_ids,
                    "int32 (N,) index into stations of the station that measured each point, "
                    "or None")
      .def_readonly("stations", &CloudArrays::stations,
                    "The scanner stations the file records: [{'name', 'origin' (x, y, z) "
                    "relative to shift, as positions, 'orientation' (w, x, y, z), 'width', "
                    "'height' (the scan's grid, 0 = none)}]; the jobs' default viewpoints")
      .def_readonly("sensor", &CloudArrays::sensor,
                    "A single-view frame's camera (an organised PCD, a PCD VIEWPOINT, a depth "
                    "frame): {'origin', 'orientation', 'width', 'height'} as a station's, "
                    "+z forward and +y down; else None")
      .def_readonly("pixels", &CloudArrays::pixels,
                    "uint32 (N,) each point's pixel (row * width + column) in an organised "
                    "sensor's grid, which the disc model fits planes on; else None")
      .def_readonly("class_names", &CloudArrays::class_names,
                    "class_names[label] when the file names its classes (S3DIS), else []")
      .def_readonly("fields", &CloudArrays::fields,
                    "Other PLY/PCD properties: name -> float32 or int32 (N,)")
      .def_readonly("dropped_nan", &CloudArrays::dropped_nan,
                    "Points dropped for a coordinate that is not finite")
      .def_readonly("skipped_lines", &CloudArrays::skipped_lines,
                    "Bad text lines skipped (skip_bad_lines=True)")
      .def_readonly("rooms", &CloudArrays::rooms, "S3DIS room folders, in reading order")
      .def_readonly("warnings", &CloudArrays::warnings,
                    "What reading found that the user should know, one sentence each (a "
                    "depth frame's depths beyond what indoor sensors measure); the jobs "
                    "report the same among their warnings")
      .def("__len__", [](const CloudArrays& c) { return c.positions.shape(0); })
      .def("__repr__", [](const CloudArrays& c) {
        return "<occlusion.Cloud of " + std::to_string(c.positions.shape(0)) + " points>";
      });

  py::class_<MeshArrays>(m, "Mesh", "A triangle mesh read by read_mesh.")
      .def_readonly("vertices", &MeshArrays::vertices, "float64 (V, 3)")
      .def_readonly("faces", &MeshArrays::faces, "uint32 (M, 3) vertex indices")
      .def_readonly("face_group", &MeshArrays::face_group, "uint32 (M,) index into group_names")
      .def_readonly("group_names", &MeshArrays::group_names, "OBJ g/o groups that have faces")
      .def_readonly("degenerate_faces", &MeshArrays::degenerate_faces,
                    "triangles of no area the reader skipped")
      .def("__len__", [](const MeshArrays& mesh) { return mesh.faces.shape(0); })
      .def("__repr__", [](const MeshArrays& mesh) {
        return "<occlusion.Mesh of " + std::to_string(mesh.faces.shape(0)) + " faces>";
      });

  // The file kinds come from the readers' own table, so none is left out.
  static const std::string read_cloud_doc = [] {
    std::string kinds;
    for (const std::string& suffix : cloud_file_suffixes()) {
      kinds += (kinds.empty() ? "" : ", ") + suffix;
    }
    return "Reads a point cloud: " + kinds +
           " (a depth frame's descriptor), a ScanNet scene folder or its "
           "_vh_clean_2.labels.ply, an S3DIS room folder or Area (docs/formats.md).\n\n" +
           R"doc(Points with a coordinate that is not finite are dropped (counted in
dropped_nan). skip_bad_lines skips text lines that do not parse (real S3DIS
has a few). InputError (an OSError and a ValueError) with path and line for a
malformed file; FileNotFoundError for a missing one.)doc";
  }();
  m.def("read_cloud", &read_cloud_arrays, py::arg("path"), py::kw_only(),
        py::arg("skip_bad_lines") = false, read_cloud_doc.c_str());
  m.def("write_cloud", &write_cloud_arrays, py::arg("path"), py::arg("positions"), py::kw_only(),
        py::arg("colours") = py::none(), py::arg("labels") = py::none(),
        py::arg("instances") = py::none(), py::arg("class_names") = py::none(),
        py::arg("intensities") = py::none(), py::arg("station_ids") = py::none(),
        py::arg("stations") = py::none(), py::arg("fields") = py::dict(),
        py::arg("format") = py::none(), py::arg("shift") = std::array<double, 3>{0.0, 0.0, 0.0},
        R"doc(Writes a point cloud as .pcd or .ply, atomically.

positions (N, 3), relative to shift (a Cloud's own shift: the file gets
position + shift, in double, when it is not zero); colours (N, 3) 0..255; labels and instances (N,) int, -1 = none;
class_names kept as header comments; intensities (N,) float; stations as
Cloud.stations gives them (kept as header comments) and station_ids (N,) int
indices into them; fields: name -> (N,) array (integer dtypes are written as
int32). format: pcd_binary_compressed (.pcd default),
pcd_binary, pcd_ascii, ply_binary (.ply default), ply_ascii.)doc");

  m.def("read_mesh", &read_mesh_arrays, py::arg("path"),
        "Reads a Wavefront OBJ mesh; polygons are fan-triangulated. InputError with path and "
        "line for a malformed file (a bad index, no faces with an area); degenerate (zero-area) "
        "faces are skipped and counted in degenerate_faces.");
  m.def(
      "write_obj",
      [](const std::string& path, py::handle vertices, py::handle faces, py::handle face_group,
         py::handle group_names, const std::string& comment) {
        const TriangleMesh mesh = mesh_from_arrays(vertices, faces, face_group, group_names);
        py::gil_scoped_release release;
        write_obj(path, mesh, comment);
      },
      py::arg("path"), py::arg("vertices"), py::arg("faces"), py::kw_only(),
      py::arg("face_group") = py::none(), py::arg("group_names") = py::none(),
      py::arg("comment") = "", "Writes a mesh as OBJ that read_mesh reads back exactly.");
  m.def(
      "write_mesh_ply",
      [](const std::string& path, py::handle vertices, py::handle faces, py::handle face_values,
         const std::string& value_name, py::handle face_group, py::handle group_names) {
        const TriangleMesh mesh = mesh_from_arrays(vertices, faces, face_group, group_names);
        const std::vector<float> values = face_values_from_array(face_values, mesh.face_count());
        py::gil_scoped_release release;
        write_mesh_ply(path, mesh, values, value_name);
      },
      py::arg("path"), py::arg("vertices"), py::arg("faces"), py::arg("face_values"),
      py::arg("value_name") = "visible_fraction", py::kw_only(), py::arg("face_group") = py::none(),
      py::arg("group_names") = py::none(),
      "Writes a mesh with one value per face as binary PLY coloured by the viridis ramp "
      "(CloudCompare and MeshLab open it).");

  m.def(
      "read_labels",
      [](const std::string& path) { return to_numpy<std::int32_t>(read_label_file(path)); },
      py::arg("path"), "Reads a label file (one integer a line, -1 = none): int32 (N,).");
  m.def(
      "write_labels",
      [](const std::string& path, py::handle labels) {
        write_label_file(path, int32_from_array(labels, "labels"));
      },
      py::arg("path"), py::arg("labels"), "Writes one label a line, atomically.");
  m.def("is_label_file", &is_label_file, py::arg("path"),
        "Whether path names a label file rather than a cloud (.labels/.label, or a .txt with "
        "one number a line).");

  m.def(
      "read_polygons",
      [](const std::string& path) {
        py::list out;
        for (std::vector<Eigen::Vector3d>& polygon : read_polygons(path)) {
          out.append(to_numpy<double>(std::move(polygon)));
        }
        return out;
      },
      py::arg("path"), "Reads an openings file: a list of float64 (k, 3) polygons.");
  m.def(
      "write_polygons",
      [](const std::string& path, const py::list& polygons) {
        write_polygons(path, polygons_from_list(polygons));
      },
      py::arg("path"), py::arg("polygons"), "Writes an openings file, atomically.");

  m.def(
      "read_csv",
      [](const std::string& path) {
        CsvTable table = read_csv(path);
        return py::make_tuple(std::move(table.columns), std::move(table.rows));
      },
      py::arg("path"), "Reads a CSV table (RFC 4180): (columns, rows), all strings.");
  m.def(
      "write_csv",
      [](const std::string& path, std::vector<std::string> columns,
         std::vector<std::vector<std::string>> rows) {
        write_csv(path, CsvTable{std::move(columns), std::move(rows)});
      },
      py::arg("path"), py::arg("columns"), py::arg("rows"), "Writes a CSV table, atomically.");

  m.def("s3dis_class_names", &s3dis_class_names,
        "The 13 S3DIS classes; an S3DIS label indexes this list.");
}

}  // namespace occlusion::python
