#include "surfel_ray_rule.hpp"

#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

namespace occlusion::surfel_ray_rule {

namespace {

static_assert(sizeof(Target) == 8 * sizeof(float), "a target is eight floats");
static_assert(sizeof(Ray) == 8 * sizeof(float), "a ray is eight floats");

// SSE's maxps and minps, written out: the scalar path must pick the same
// operand in every case the lanes do.
float max_ps(float a, float b) {
  return a > b ? a : b;
}
float min_ps(float a, float b) {
  return a < b ? a : b;
}

// A disc's reach once its plane's sine is known (`oriented` false: a sphere).
float reach_of(float radius, bool oriented, float sine, float thickness) {
  if (!oriented) return kMaxReachPerRadius * radius;
  const float reach = kThicknessSigmas * thickness / max_ps(sine, kMinSine);
  return min_ps(max_ps(reach, kMinReachPerRadius * radius), kMaxReachPerRadius * radius);
}

#if defined(__SSE2__)

__m128 select(__m128 mask, __m128 yes, __m128 no) {
  return _mm_or_ps(_mm_and_ps(mask, yes), _mm_andnot_ps(mask, no));
}

// Four targets' rays: the same operations as ray() below, lane by lane.
void four_rays(const Viewpoint& viewpoint, const Target* targets, Ray* out) {
  float in[32];
  std::memcpy(in, targets, sizeof(in));
  // Rows of the transposes: target k's first and last four floats.
  __m128 cx = _mm_loadu_ps(in), cy = _mm_loadu_ps(in + 8), cz = _mm_loadu_ps(in + 16),
         radius = _mm_loadu_ps(in + 24);
  _MM_TRANSPOSE4_PS(cx, cy, cz, radius);
  __m128 nx = _mm_loadu_ps(in + 4), ny = _mm_loadu_ps(in + 12), nz = _mm_loadu_ps(in + 20),
         thickness = _mm_loadu_ps(in + 28);
  _MM_TRANSPOSE4_PS(nx, ny, nz, thickness);

  const __m128 dx = _mm_sub_ps(cx, _mm_set1_ps(viewpoint.position.x()));
  const __m128 dy = _mm_sub_ps(cy, _mm_set1_ps(viewpoint.position.y()));
  const __m128 dz = _mm_sub_ps(cz, _mm_set1_ps(viewpoint.position.z()));
  const __m128 length = _mm_sqrt_ps(
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz)));
  const __m128 inverse = _mm_div_ps(_mm_set1_ps(1.0f), length);
  const __m128 dot =
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, dx), _mm_mul_ps(ny, dy)), _mm_mul_ps(nz, dz));
  const __m128 sine = _mm_mul_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), dot), inverse);

  __m128 reach;
  if (viewpoint.fixed_reach >= 0.0f) {
    reach = _mm_set1_ps(viewpoint.fixed_reach);
  } else {
    const __m128 zero = _mm_setzero_ps();
    const __m128 oriented = _mm_or_ps(_mm_or_ps(_mm_cmpneq_ps(nx, zero), _mm_cmpneq_ps(ny, zero)),
                                      _mm_cmpneq_ps(nz, zero));
    const __m128 widest = _mm_mul_ps(_mm_set1_ps(kMaxReachPerRadius), radius);
    const __m128 surface =
        _mm_min_ps(_mm_max_ps(_mm_div_ps(_mm_mul_ps(_mm_set1_ps(kThicknessSigmas), thickness),
                                         _mm_max_ps(sine, _mm_set1_ps(kMinSine))),
                              _mm_mul_ps(_mm_set1_ps(kMinReachPerRadius), radius)),
                   widest);
    reach = select(_mm_cmpgt_ps(length, zero), select(oriented, surface, widest), zero);
  }
  const __m128 near = _mm_set1_ps(viewpoint.near_viewpoint);
  const __m128 open = _mm_cmpgt_ps(length, _mm_add_ps(near, reach));
  const __m128 one = _mm_set1_ps(1.0f);
  __m128 t_min = select(open, _mm_mul_ps(near, inverse), one);
  __m128 t_max = select(open, _mm_sub_ps(one, _mm_mul_ps(reach, inverse)), _mm_setzero_ps());

  __m128 ox = _mm_set1_ps(viewpoint.position.x()), oy = _mm_set1_ps(viewpoint.position.y()),
         oz = _mm_set1_ps(viewpoint.position.z()), rx = dx;
  _MM_TRANSPOSE4_PS(ox, oy, oz, rx);
  __m128 ry = dy, rz = dz;
  _MM_TRANSPOSE4_PS(ry, rz, t_min, t_max);
  float result[32];
  _mm_storeu_ps(result, ox);
  _mm_storeu_ps(result + 4, ry);
  _mm_storeu_ps(result + 8, oy);
  _mm_storeu_ps(result + 12, rz);
  _mm_storeu_ps(result + 16, oz);
  _mm_storeu_ps(result + 20, t_min);
  _mm_storeu_ps(result + 24, rx);
  _mm_storeu_ps(result + 28, t_max);
  std::memcpy(static_cast<void*>(out), result, sizeof(result));
}

#endif

}  // namespace

Ray ray(const Viewpoint& viewpoint, const Target& target) {
  const Surfel& surfel = target.surfel;
  const float dx = surfel.center.x() - viewpoint.position.x();
  const float dy = surfel.center.y() - viewpoint.position.y();
  const float dz = surfel.center.z() - viewpoint.position.z();
  const float length = std::sqrt((dx * dx + dy * dy) + dz * dz);
  const float inverse = 1.0f / length;
  const float sine =
      std::abs((surfel.normal.x() * dx + surfel.normal.y() * dy) + surfel.normal.z() * dz) *
      inverse;
  float reach = 0.0f;
  if (viewpoint.fixed_reach >= 0.0f) {
    reach = viewpoint.fixed_reach;
  } else if (length > 0.0f) {
    reach = reach_of(surfel.radius, surfel.oriented(), sine, target.thickness);
  }
  Ray out;
  out.origin = viewpoint.position;
  out.direction = Eigen::Vector3f(dx, dy, dz);
  const bool open = length > viewpoint.near_viewpoint + reach;
  out.t_min = open ? viewpoint.near_viewpoint * inverse : 1.0f;
  out.t_max = open ? 1.0f - reach * inverse : 0.0f;
  return out;
}

void rays(const Viewpoint& viewpoint, const Target* targets, std::size_t count, Ray* out) {
  std::size_t k = 0;
#if defined(__SSE2__)
  for (; k + 4 <= count; k += 4) four_rays(viewpoint, targets + k, out + k);
#endif
  for (; k < count; ++k) out[k] = ray(viewpoint, targets[k]);
}

}  // namespace occlusion::surfel_ray_rule
