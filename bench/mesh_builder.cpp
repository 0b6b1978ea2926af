#include "mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace occlusion::bench {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

MeshBuilder::MeshBuilder(double density) : density_(density) {
  if (!(density > 0.0) || !std::isfinite(density)) {
    throw std::invalid_argument("MeshBuilder: density must be finite and > 0");
  }
}

void MeshBuilder::begin_group(const std::string& name) {
  mesh_.group_names.push_back(name);
}

std::size_t MeshBuilder::divisions(double length, std::size_t minimum) const {
  // The small slack keeps an exact product such as 2.0000000001 from gaining a cell.
  const double cells = std::ceil(length * density_ - 1e-9);
  return std::max(minimum, static_cast<std::size_t>(std::max(cells, 0.0)));
}

std::uint32_t MeshBuilder::add_vertex(const Eigen::Vector3d& p) {
  mesh_.vertices.push_back(p);
  return static_cast<std::uint32_t>(mesh_.vertices.size() - 1);
}

void MeshBuilder::add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (mesh_.group_names.empty()) {
    throw std::logic_error("MeshBuilder: begin_group must come before any shape");
  }
  mesh_.faces.push_back({a, b, c});
  mesh_.face_group.push_back(static_cast<std::uint32_t>(mesh_.group_names.size() - 1));
}

void MeshBuilder::add_panel(const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                            const Eigen::Vector3d& v) {
  const std::size_t nu = divisions(u.norm(), 1);
  const std::size_t nv = divisions(v.norm(), 1);
  const auto first = static_cast<std::uint32_t>(mesh_.vertices.size());
  for (std::size_t j = 0; j <= nv; ++j) {
    for (std::size_t i = 0; i <= nu; ++i) {
      // i / nu is exactly 1 at the far edge, so panels that share an edge share its vertices'
      // positions.
      add_vertex(origin + u * (static_cast<double>(i) / static_cast<double>(nu)) +
                 v * (static_cast<double>(j) / static_cast<double>(nv)));
    }
  }
  const auto at = [&](std::size_t i, std::size_t j) {
    return static_cast<std::uint32_t>(first + j * (nu + 1) + i);
  };
  for (std::size_t j = 0; j < nv; ++j) {
    for (std::size_t i = 0; i < nu; ++i) {
      add_triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      add_triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
}

void MeshBuilder::add_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3d size = hi - lo;
  const Eigen::Vector3d dx(size.x(), 0.0, 0.0);
  const Eigen::Vector3d dy(0.0, size.y(), 0.0);
  const Eigen::Vector3d dz(0.0, 0.0, size.z());
  add_panel(lo, dy, dx);                                       // -z
  add_panel(Eigen::Vector3d(lo.x(), lo.y(), hi.z()), dx, dy);  // +z
  add_panel(lo, dx, dz);                                       // -y
  add_panel(Eigen::Vector3d(lo.x(), hi.y(), lo.z()), dz, dx);  // +y
  add_panel(lo, dz, dy);                                       // -x
  add_panel(Eigen::Vector3d(hi.x(), lo.y(), lo.z()), dy, dz);  // +x
}

void MeshBuilder::add_lathe(const Eigen::Vector2d& axis, const std::vector<ProfilePoint>& profile) {
  if (profile.size() < 2) {
    throw std::invalid_argument("MeshBuilder: a lathe profile needs at least two points");
  }
  std::vector<ProfilePoint> refined{profile.front()};
  double max_r = profile.front().r;
  for (std::size_t k = 1; k < profile.size(); ++k) {
    const ProfilePoint& a = profile[k - 1];
    const ProfilePoint& b = profile[k];
    const std::size_t n = divisions(std::hypot(b.r - a.r, b.z - a.z), 1);
    for (std::size_t s = 1; s <= n; ++s) {
      const double f = static_cast<double>(s) / static_cast<double>(n);
      refined.push_back({a.r + (b.r - a.r) * f, a.z + (b.z - a.z) * f});
    }
    max_r = std::max(max_r, b.r);
  }
  revolve(axis, refined, divisions(2.0 * kPi * max_r, 8));
}

void MeshBuilder::add_sphere(const Eigen::Vector3d& centre, double radius) {
  const std::size_t stacks = divisions(kPi * radius, 4);
  std::vector<ProfilePoint> profile;
  for (std::size_t i = 0; i <= stacks; ++i) {
    const double theta = kPi * static_cast<double>(i) / static_cast<double>(stacks);
    // Exact zeros at the poles make them single apex vertices, not rings of coincident ones.
    const double r = (i == 0 || i == stacks) ? 0.0 : radius * std::sin(theta);
    profile.push_back({r, centre.z() - radius * std::cos(theta)});
  }
  revolve(centre.head<2>(), profile, divisions(2.0 * kPi * radius, 8));
}

void MeshBuilder::revolve(const Eigen::Vector2d& axis, const std::vector<ProfilePoint>& profile,
                          std::size_t slices) {
  // first[k]: index of ring k's first vertex; an r == 0 point is one apex vertex.
  std::vector<std::uint32_t> first;
  for (const ProfilePoint& p : profile) {
    if (p.r < 0.0) throw std::invalid_argument("MeshBuilder: negative lathe radius");
    if (p.r == 0.0) {
      first.push_back(add_vertex(Eigen::Vector3d(axis.x(), axis.y(), p.z)));
      continue;
    }
    first.push_back(static_cast<std::uint32_t>(mesh_.vertices.size()));
    for (std::size_t j = 0; j < slices; ++j) {
      const double phi = 2.0 * kPi * static_cast<double>(j) / static_cast<double>(slices);
      add_vertex(
          Eigen::Vector3d(axis.x() + p.r * std::cos(phi), axis.y() + p.r * std::sin(phi), p.z));
    }
  }
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const ProfilePoint& a = profile[k];
    const ProfilePoint& b = profile[k + 1];
    if ((a.r == b.r && a.z == b.z) || (a.r == 0.0 && b.r == 0.0)) {
      throw std::invalid_argument("MeshBuilder: lathe profile has a zero-area band");
    }
    const auto ring = [&](std::size_t index, std::size_t j) {
      return profile[index].r == 0.0 ? first[index]
                                     : static_cast<std::uint32_t>(first[index] + j % slices);
    };
    // The band between rings k and k + 1 as quads (lower j, lower j+1, upper j+1,
    // upper j); a quad with a collapsed side is one triangle.
    for (std::size_t j = 0; j < slices; ++j) {
      if (a.r != 0.0) add_triangle(ring(k, j), ring(k, j + 1), ring(k + 1, j + 1));
      if (b.r != 0.0) add_triangle(ring(k, j), ring(k + 1, j + 1), ring(k + 1, j));
    }
  }
}

}  // namespace occlusion::bench
