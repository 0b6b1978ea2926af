#pragma once
// Float lanes for packet traversal, one set of operations per instruction set:
// 8 lanes with SSE2 or AVX2, 16 with AVX-512. octree_packet.hpp includes the
// traversal body once per set, each copy in its own namespace beside the
// matching lanes, so one source serves all, and a copy runs only where the CPU
// has its instructions (runtime dispatch, no -march flags). Lane j holds ray j
// of the packet.

#include <immintrin.h>

namespace occlusion::octree_detail {

namespace packet_sse2 {

inline constexpr unsigned kLanes = 8;

struct Lanes {
  __m128 a, b;  // lanes 0-3, 4-7
};
inline Lanes load(const float* p) {
  return {_mm_load_ps(p), _mm_load_ps(p + 4)};
}
inline Lanes broadcast(float x) {
  return {_mm_set1_ps(x), _mm_set1_ps(x)};
}
inline Lanes mul(Lanes x, Lanes y) {
  return {_mm_mul_ps(x.a, y.a), _mm_mul_ps(x.b, y.b)};
}
inline Lanes sub(Lanes x, Lanes y) {
  return {_mm_sub_ps(x.a, y.a), _mm_sub_ps(x.b, y.b)};
}
inline Lanes min(Lanes x, Lanes y) {
  return {_mm_min_ps(x.a, y.a), _mm_min_ps(x.b, y.b)};
}
inline Lanes max(Lanes x, Lanes y) {
  return {_mm_max_ps(x.a, y.a), _mm_max_ps(x.b, y.b)};
}
inline void store(float* p, Lanes x) {
  _mm_store_ps(p, x.a);
  _mm_store_ps(p + 4, x.b);
}
// Bit j set where x[j] <= y[j] (false for NaN).
inline unsigned less_equal(Lanes x, Lanes y) {
  return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(x.a, y.a)) |
                               (_mm_movemask_ps(_mm_cmple_ps(x.b, y.b)) << 4));
}

}  // namespace packet_sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace packet_avx2 {

inline constexpr unsigned kLanes = 8;

// No FMA: a fused multiply-add rounds differently from the single-ray path,
// and results must not depend on the CPU. AVX-512 enables FMA, so the core is
// compiled with -ffp-contract=off (CMakeLists.txt) to keep GCC from fusing.
struct Lanes {
  __m256 v;
};
inline Lanes load(const float* p) {
  return {_mm256_load_ps(p)};
}
inline Lanes broadcast(float x) {
  return {_mm256_set1_ps(x)};
}
inline Lanes mul(Lanes x, Lanes y) {
  return {_mm256_mul_ps(x.v, y.v)};
}
inline Lanes sub(Lanes x, Lanes y) {
  return {_mm256_sub_ps(x.v, y.v)};
}
inline Lanes min(Lanes x, Lanes y) {
  return {_mm256_min_ps(x.v, y.v)};
}
inline Lanes max(Lanes x, Lanes y) {
  return {_mm256_max_ps(x.v, y.v)};
}
inline void store(float* p, Lanes x) {
  _mm256_store_ps(p, x.v);
}
inline unsigned less_equal(Lanes x, Lanes y) {
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(x.v, y.v, _CMP_LE_OQ)));
}

}  // namespace packet_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f")
namespace packet_avx512 {

inline constexpr unsigned kLanes = 16;

struct Lanes {
  __m512 v;
};
inline Lanes load(const float* p) {
  return {_mm512_load_ps(p)};
}
inline Lanes broadcast(float x) {
  return {_mm512_set1_ps(x)};
}
inline Lanes mul(Lanes x, Lanes y) {
  return {_mm512_mul_ps(x.v, y.v)};
}
inline Lanes sub(Lanes x, Lanes y) {
  return {_mm512_sub_ps(x.v, y.v)};
}
inline Lanes min(Lanes x, Lanes y) {
  return {_mm512_min_ps(x.v, y.v)};
}
inline Lanes max(Lanes x, Lanes y) {
  return {_mm512_max_ps(x.v, y.v)};
}
inline void store(float* p, Lanes x) {
  _mm512_store_ps(p, x.v);
}
inline unsigned less_equal(Lanes x, Lanes y) {
  return static_cast<unsigned>(_mm512_cmp_ps_mask(x.v, y.v, _CMP_LE_OQ));
}

}  // namespace packet_avx512
#pragma GCC pop_options

}  // namespace occlusion::octree_detail
