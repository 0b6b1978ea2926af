#pragma once
#include <Eigen/Core>

namespace occlusion {

// The seed document's barycentric formula (listing 4.5): with r1, r2 uniform in
// [0,1), alpha = 1 - sqrt(r1), beta = r2 sqrt(r1), the point
// alpha v0 + beta v1 + (1 - alpha - beta) v2 is uniform on the triangle.
Eigen::Vector3d sample_triangle(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                const Eigen::Vector3d& v2, double r1, double r2);

// The seed's spherical light source (listing 4.2): theta = 2 pi r1 (azimuth),
// phi = acos(2 r2 - 1) (polar), giving a unit direction uniform on the sphere.
Eigen::Vector3d sample_sphere_direction(double r1, double r2);

}  // namespace occlusion
