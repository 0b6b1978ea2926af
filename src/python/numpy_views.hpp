#pragma once
// Reading numpy arrays in place and handing C++ vectors to numpy.
//
// Inputs are read where they lie, whatever their strides: float32 and float64
// without a copy (other numeric dtypes are converted once). The views hold a
// reference to their array, so they may be read from worker threads while the
// GIL is released. Outputs move the C++ vector into the array's owner: no copy.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/core/mesh.hpp"

namespace occlusion::python {

// An (N, 3) array of coordinates, or (3,) when `broadcast_single` allows one
// point for every row. ValueError naming `name` for another shape.
class Vec3View {
 public:
  Vec3View(const pybind11::handle& object, const std::string& name, bool broadcast_single = false);

  std::size_t size() const { return rows_; }
  // Rows of a (3,) array all read as that one point.
  bool broadcast() const { return broadcast_; }
  Eigen::Vector3f operator[](std::size_t row) const { return read<float>(row); }
  Eigen::Vector3d point_d(std::size_t row) const { return read<double>(row); }

 private:
  template <class T>
  Eigen::Matrix<T, 3, 1> read(std::size_t row) const {
    const char* base = data_ + (broadcast_ ? 0 : static_cast<pybind11::ssize_t>(row) * row_stride_);
    Eigen::Matrix<T, 3, 1> out;
    for (int c = 0; c < 3; ++c) {
      const char* at = base + c * column_stride_;
      out[c] = is_double_ ? static_cast<T>(*reinterpret_cast<const double*>(at))
                          : static_cast<T>(*reinterpret_cast<const float*>(at));
    }
    return out;
  }

  pybind11::array array_;
  const char* data_ = nullptr;
  pybind11::ssize_t row_stride_ = 0, column_stride_ = 0;
  std::size_t rows_ = 0;
  bool is_double_ = false;
  bool broadcast_ = false;
};

// A float per row: a Python number for every row, or an (N,) array.
class ScalarView {
 public:
  ScalarView(const pybind11::handle& object, const std::string& name);

  // ValueError naming the argument when an array's length is not `rows`.
  void expect_rows(std::size_t rows) const;
  float operator[](std::size_t row) const {
    return data_ ? *reinterpret_cast<const double*>(data_ +
                                                    static_cast<pybind11::ssize_t>(row) * stride_)
                 : value_;
  }

 private:
  pybind11::array_t<double> array_;
  const char* data_ = nullptr;  // null: one value for every row
  pybind11::ssize_t stride_ = 0;
  float value_ = 0.0f;
  std::size_t rows_ = 0;
  std::string name_;
};

// Integer arrays, checked to be integers (a float array is refused rather than
// truncated). Copies only when the dtype is not int64.
pybind11::array_t<std::int64_t> integer_array(const pybind11::handle& object,
                                              const std::string& name);
// (M, 3) vertex indices, each in [0, vertex_count).
std::vector<std::array<std::uint32_t, 3>> faces_from_array(const pybind11::handle& object,
                                                           std::size_t vertex_count);
// (N,) int32 labels or ids; -1 and up fit int32, anything else is refused.
std::vector<std::int32_t> int32_from_array(const pybind11::handle& object, const std::string& name);
std::vector<std::array<std::uint8_t, 3>> colours_from_array(const pybind11::handle& object,
                                                            const std::string& name);
std::vector<Eigen::Vector3f> points_from_array(const pybind11::handle& object,
                                               const std::string& name);
// A mesh from (V, 3) vertices and (M, 3) faces; face_group (M,) and
// group_names may be None (one group "default"). Checked by TriangleMesh::validate.
TriangleMesh mesh_from_arrays(const pybind11::handle& vertices, const pybind11::handle& faces,
                              const pybind11::handle& face_group,
                              const pybind11::handle& group_names);

// A numpy array that owns `values`, moved in: no copy. Shape (n,) when T is
// Scalar, (n, k) when T packs k Scalars (Eigen::Vector3f, std::array<uint8_t, 3>).
template <class Scalar, class T>
pybind11::array_t<Scalar> to_numpy(std::vector<T>&& values) {
  static_assert(sizeof(T) % sizeof(Scalar) == 0, "T must be a packed row of Scalars");
  constexpr auto columns = static_cast<pybind11::ssize_t>(sizeof(T) / sizeof(Scalar));
  auto* owned = new std::vector<T>(std::move(values));
  pybind11::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  const auto rows = static_cast<pybind11::ssize_t>(owned->size());
  const auto* data = reinterpret_cast<const Scalar*>(owned->data());
  if (columns == 1) return pybind11::array_t<Scalar>({rows}, data, owner);
  return pybind11::array_t<Scalar>({rows, columns}, data, owner);
}

}  // namespace occlusion::python
