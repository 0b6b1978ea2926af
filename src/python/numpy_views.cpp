#include "numpy_views.hpp"

#include <pybind11/stl.h>

#include <limits>
#include <type_traits>

namespace py = pybind11;

namespace occlusion::python {
namespace {

[[noreturn]] void bad_argument(const std::string& name, const std::string& what) {
  throw py::value_error(name + ": " + what);
}

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    if (d > 0) text += ", ";
    text += std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

bool is_numeric(const py::array& array) {
  const char kind = array.dtype().kind();
  return kind == 'f' || kind == 'i' || kind == 'u' || kind == 'b';
}

}  // namespace

Vec3View::Vec3View(const py::handle& object, const std::string& name, bool broadcast_single) {
  py::array any = py::array::ensure(object);
  if (!any || !is_numeric(any)) bad_argument(name, "expected a numeric array of points");
  if (py::isinstance<py::array_t<float>>(any)) {  // native float32, any strides
    array_ = any;
  } else {
    is_double_ = true;
    array_ = py::array_t<double, py::array::forcecast>::ensure(any);  // float64: no copy
  }
  if (array_.ndim() == 1 && array_.shape(0) == 3 && broadcast_single) {
    broadcast_ = true;
    rows_ = 1;
    column_stride_ = array_.strides(0);
  } else if (array_.ndim() == 2 && array_.shape(1) == 3) {
    rows_ = static_cast<std::size_t>(array_.shape(0));
    row_stride_ = array_.strides(0);
    column_stride_ = array_.strides(1);
  } else {
    bad_argument(name, std::string("expected shape (N, 3)") + (broadcast_single ? " or (3,)" : "") +
                           ", got " + shape_text(array_));
  }
  data_ = static_cast<const char*>(array_.data());
}

ScalarView::ScalarView(const py::handle& object, const std::string& name) : name_(name) {
  if (py::isinstance<py::float_>(object) || py::isinstance<py::int_>(object)) {
    value_ = object.cast<float>();
    return;
  }
  py::array any = py::array::ensure(object);
  if (!any || !is_numeric(any)) bad_argument(name, "expected a number or an array of numbers");
  array_ = py::array_t<double, py::array::forcecast>::ensure(any);
  if (array_.ndim() == 0) {
    value_ = static_cast<float>(*array_.data());
    return;
  }
  if (array_.ndim() != 1) bad_argument(name, "expected shape (N,), got " + shape_text(array_));
  data_ = reinterpret_cast<const char*>(array_.data());
  stride_ = array_.strides(0);
  rows_ = static_cast<std::size_t>(array_.shape(0));
}

void ScalarView::expect_rows(std::size_t rows) const {
  if (data_ && rows_ != rows) {
    bad_argument(name_,
                 "has " + std::to_string(rows_) + " values for " + std::to_string(rows) + " rays");
  }
}

namespace {

py::array integer_or_refuse(const py::handle& object, const std::string& name) {
  py::array any = py::array::ensure(object);
  const char kind = any ? any.dtype().kind() : '?';
  if (!any || (kind != 'i' && kind != 'u' && !(kind == 'f' && any.size() == 0))) {
    bad_argument(name, "expected an integer array");
  }
  return any;
}

bool is_uint64(const py::array& array) {
  return array.dtype().kind() == 'u' && array.itemsize() == 8;
}

template <class Index>
std::vector<std::array<std::uint32_t, 3>> faces_of(const py::array_t<Index>& array,
                                                   std::size_t vertex_count) {
  if (array.ndim() != 2 || array.shape(1) != 3) {
    bad_argument("faces", "expected shape (M, 3), got " + shape_text(array));
  }
  const auto view = array.template unchecked<2>();
  std::vector<std::array<std::uint32_t, 3>> faces(static_cast<std::size_t>(view.shape(0)));
  for (py::ssize_t f = 0; f < view.shape(0); ++f) {
    for (py::ssize_t c = 0; c < 3; ++c) {
      const Index index = view(f, c);
      bool outside = static_cast<std::uint64_t>(index) >= vertex_count;
      if constexpr (std::is_signed_v<Index>) outside = outside || index < 0;
      if (outside) {
        bad_argument("faces", "face " + std::to_string(f) + " uses vertex " +
                                  std::to_string(index) + ", outside [0, " +
                                  std::to_string(vertex_count) + ")");
      }
      faces[static_cast<std::size_t>(f)][static_cast<std::size_t>(c)] =
          static_cast<std::uint32_t>(index);
    }
  }
  return faces;
}

}  // namespace

py::array_t<std::int64_t> integer_array(const py::handle& object, const std::string& name) {
  const py::array any = integer_or_refuse(object, name);
  // uint64 past 2^63 would wrap to a negative int64: a face index reported
  // negative, a label taken for -1 (unlabelled).
  if (is_uint64(any)) {
    const auto flat =
        py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(any);
    for (py::ssize_t i = 0; i < flat.size(); ++i) {
      const std::uint64_t value = flat.data()[i];
      if (value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        bad_argument(name, "value " + std::to_string(value) + " at " + std::to_string(i) +
                               (any.ndim() == 1 ? "" : " (flat)") + " is beyond 2^63 - 1");
      }
    }
  }
  return py::array_t<std::int64_t, py::array::forcecast>::ensure(any);
}

std::vector<std::array<std::uint32_t, 3>> faces_from_array(const py::handle& object,
                                                           std::size_t vertex_count) {
  const py::array any = integer_or_refuse(object, "faces");
  if (is_uint64(any)) {
    return faces_of(py::array_t<std::uint64_t, py::array::forcecast>::ensure(any), vertex_count);
  }
  return faces_of(integer_array(any, "faces"), vertex_count);
}

std::vector<std::int32_t> int32_from_array(const py::handle& object, const std::string& name) {
  const py::array_t<std::int64_t> array = integer_array(object, name);
  if (array.ndim() != 1) bad_argument(name, "expected shape (N,), got " + shape_text(array));
  const auto view = array.unchecked<1>();
  std::vector<std::int32_t> values(static_cast<std::size_t>(view.shape(0)));
  for (py::ssize_t i = 0; i < view.shape(0); ++i) {
    if (view(i) < -1 || view(i) > std::numeric_limits<std::int32_t>::max()) {
      bad_argument(name, "value " + std::to_string(view(i)) + " at " + std::to_string(i) +
                             " is outside [-1, 2^31)");
    }
    values[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(view(i));
  }
  return values;
}

std::vector<std::array<std::uint8_t, 3>> colours_from_array(const py::handle& object,
                                                            const std::string& name) {
  const py::array_t<std::int64_t> array = integer_array(object, name);
  if (array.ndim() != 2 || array.shape(1) != 3) {
    bad_argument(name, "expected shape (N, 3) of 0..255, got " + shape_text(array));
  }
  const auto view = array.unchecked<2>();
  std::vector<std::array<std::uint8_t, 3>> colours(static_cast<std::size_t>(view.shape(0)));
  for (py::ssize_t i = 0; i < view.shape(0); ++i) {
    for (py::ssize_t c = 0; c < 3; ++c) {
      if (view(i, c) < 0 || view(i, c) > 255) {
        bad_argument(name, "value " + std::to_string(view(i, c)) + " at row " + std::to_string(i) +
                               " is outside 0..255");
      }
      colours[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] =
          static_cast<std::uint8_t>(view(i, c));
    }
  }
  return colours;
}

std::vector<Eigen::Vector3f> points_from_array(const py::handle& object, const std::string& name) {
  const Vec3View view(object, name);
  std::vector<Eigen::Vector3f> points(view.size());
  for (std::size_t i = 0; i < view.size(); ++i) points[i] = view[i];
  return points;
}

TriangleMesh mesh_from_arrays(const py::handle& vertices, const py::handle& faces,
                              const py::handle& face_group, const py::handle& group_names) {
  TriangleMesh mesh;
  const Vec3View view(vertices, "vertices");
  mesh.vertices.resize(view.size());
  for (std::size_t i = 0; i < view.size(); ++i) mesh.vertices[i] = view.point_d(i);
  mesh.faces = faces_from_array(faces, view.size());
  if (face_group.is_none() != group_names.is_none()) {
    throw py::value_error("face_group and group_names: give both or neither");
  }
  if (face_group.is_none()) {
    mesh.face_group.assign(mesh.faces.size(), 0);
    mesh.group_names = {"default"};
  } else {
    for (const std::int32_t group : int32_from_array(face_group, "face_group")) {
      if (group < 0) throw py::value_error("face_group: -1 is not a group");
      mesh.face_group.push_back(static_cast<std::uint32_t>(group));
    }
    mesh.group_names = group_names.cast<std::vector<std::string>>();
  }
  mesh.validate();
  return mesh;
}

}  // namespace occlusion::python
