#pragma once
// Float lanes for packet traversal, one set of operations per instruction set:
// 8 lanes with SSE2 or AVX2, 16 with AVX-512. octree_packet.hpp includes the
// traversal body once per set, each copy in its own namespace beside the
// matching lanes, so one source serves all, and a copy runs only where the CPU
// has its instructions (runtime dispatch, no -march flags). Lane j holds ray j
// of the packet.

#include <immintrin.h>

#include <cstdint>

namespace occlusion::octree_detail {

namespace packet_sse2 {

inline constexpr unsigned kLanes = 8;

struct Lanes {
  __m128 a, b;  // lanes 0-3, 4-7
  Lanes() = default;
  Lanes(__m128 low, __m128 high) : a(low), b(high) {}
  Lanes(float x) : a(_mm_set1_ps(x)), b(_mm_set1_ps(x)) {}  // NOLINT: broadcast, implicit
};
inline Lanes load(const float* p) {
  return {_mm_load_ps(p), _mm_load_ps(p + 4)};
}
inline Lanes broadcast(float x) {
  return Lanes(x);
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
inline unsigned less(Lanes x, Lanes y) {
  return static_cast<unsigned>(_mm_movemask_ps(_mm_cmplt_ps(x.a, y.a)) |
                               (_mm_movemask_ps(_mm_cmplt_ps(x.b, y.b)) << 4));
}
inline Lanes add(Lanes x, Lanes y) {
  return {_mm_add_ps(x.a, y.a), _mm_add_ps(x.b, y.b)};
}
inline Lanes div(Lanes x, Lanes y) {
  return {_mm_div_ps(x.a, y.a), _mm_div_ps(x.b, y.b)};
}
inline Lanes sqrt(Lanes x) {
  return {_mm_sqrt_ps(x.a), _mm_sqrt_ps(x.b)};
}
inline Lanes bit_and(Lanes x, Lanes y) {
  return {_mm_and_ps(x.a, y.a), _mm_and_ps(x.b, y.b)};
}
inline Lanes bit_or(Lanes x, Lanes y) {
  return {_mm_or_ps(x.a, y.a), _mm_or_ps(x.b, y.b)};
}
inline Lanes bit_xor(Lanes x, Lanes y) {
  return {_mm_xor_ps(x.a, y.a), _mm_xor_ps(x.b, y.b)};
}
inline Lanes select(unsigned mask, Lanes if_set, Lanes if_clear) {
  const __m128i bits = _mm_set_epi32(8, 4, 2, 1);
  const __m128 low = _mm_castsi128_ps(
      _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(static_cast<int>(mask)), bits), bits));
  const __m128 high = _mm_castsi128_ps(
      _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(static_cast<int>(mask >> 4)), bits), bits));
  return {_mm_or_ps(_mm_and_ps(low, if_set.a), _mm_andnot_ps(low, if_clear.a)),
          _mm_or_ps(_mm_and_ps(high, if_set.b), _mm_andnot_ps(high, if_clear.b))};
}
// Bit j set where ids[j] == id.
inline unsigned equal_ids(const std::uint32_t* ids, std::uint32_t id) {
  const __m128i target = _mm_set1_epi32(static_cast<int>(id));
  const __m128i low =
      _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(ids)), target);
  const __m128i high =
      _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(ids + 4)), target);
  return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(low)) |
                               (_mm_movemask_ps(_mm_castsi128_ps(high)) << 4));
}

// Lane j = *(base + offset[j]) (offsets in floats): rays gathered by component.
inline Lanes gather(const float* base, const std::int32_t* offset) {
  alignas(16) float lanes[kLanes];
  for (unsigned j = 0; j < kLanes; ++j) lanes[j] = base[offset[j]];
  return load(lanes);
}

// Lane j's ray is the eight floats at base + offset[j]; load_rays puts them
// in lanes where that beats gathers and says whether it did: not here.
inline bool load_rays(const float*, const std::int32_t*, Lanes*) {
  return false;
}

// The smallest and largest lane (a NaN lane may or may not be passed over).
inline float reduce_min(Lanes x) {
  __m128 m = _mm_min_ps(x.a, x.b);
  m = _mm_min_ps(m, _mm_movehl_ps(m, m));
  return _mm_cvtss_f32(_mm_min_ss(m, _mm_shuffle_ps(m, m, 1)));
}
inline float reduce_max(Lanes x) {
  __m128 m = _mm_max_ps(x.a, x.b);
  m = _mm_max_ps(m, _mm_movehl_ps(m, m));
  return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
}

// Eight lanes, one per child slot of a node: these lanes themselves.
using SlotLanes = Lanes;
inline SlotLanes load_slots(const float* p) {
  return load(p);
}

#include "octree_lane_group_whole.inc"
#include "octree_lane_operators.inc"

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
  Lanes() = default;
  Lanes(__m256 x) : v(x) {}                 // NOLINT: implicit
  Lanes(float x) : v(_mm256_set1_ps(x)) {}  // NOLINT: broadcast, implicit
};
inline Lanes load(const float* p) {
  return {_mm256_load_ps(p)};
}
inline Lanes broadcast(float x) {
  return Lanes(x);
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
inline unsigned less(Lanes x, Lanes y) {
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(x.v, y.v, _CMP_LT_OQ)));
}
inline Lanes add(Lanes x, Lanes y) {
  return {_mm256_add_ps(x.v, y.v)};
}
inline Lanes div(Lanes x, Lanes y) {
  return {_mm256_div_ps(x.v, y.v)};
}
inline Lanes sqrt(Lanes x) {
  return {_mm256_sqrt_ps(x.v)};
}
inline Lanes bit_and(Lanes x, Lanes y) {
  return {_mm256_and_ps(x.v, y.v)};
}
inline Lanes bit_or(Lanes x, Lanes y) {
  return {_mm256_or_ps(x.v, y.v)};
}
inline Lanes bit_xor(Lanes x, Lanes y) {
  return {_mm256_xor_ps(x.v, y.v)};
}
inline Lanes select(unsigned mask, Lanes if_set, Lanes if_clear) {
  const __m256i bits = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
  const __m256i set =
      _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(mask)), bits), bits);
  return {_mm256_blendv_ps(if_clear.v, if_set.v, _mm256_castsi256_ps(set))};
}
inline unsigned equal_ids(const std::uint32_t* ids, std::uint32_t id) {
  const __m256i equal =
      _mm256_cmpeq_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(ids)),
                         _mm256_set1_epi32(static_cast<int>(id)));
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(equal)));
}

inline Lanes gather(const float* base, const std::int32_t* offset) {
  return {
      _mm256_i32gather_ps(base, _mm256_load_si256(reinterpret_cast<const __m256i*>(offset)), 4)};
}

// Eight rows of eight floats, transposed: rows[i][j] <-> rows[j][i].
inline void transpose8(__m256* rows) {
  const __m256 t0 = _mm256_unpacklo_ps(rows[0], rows[1]), t1 = _mm256_unpackhi_ps(rows[0], rows[1]);
  const __m256 t2 = _mm256_unpacklo_ps(rows[2], rows[3]), t3 = _mm256_unpackhi_ps(rows[2], rows[3]);
  const __m256 t4 = _mm256_unpacklo_ps(rows[4], rows[5]), t5 = _mm256_unpackhi_ps(rows[4], rows[5]);
  const __m256 t6 = _mm256_unpacklo_ps(rows[6], rows[7]), t7 = _mm256_unpackhi_ps(rows[6], rows[7]);
  const __m256 u0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 u1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 u2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 u3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 u4 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 u5 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 u6 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 u7 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(3, 2, 3, 2));
  rows[0] = _mm256_permute2f128_ps(u0, u4, 0x20);
  rows[1] = _mm256_permute2f128_ps(u1, u5, 0x20);
  rows[2] = _mm256_permute2f128_ps(u2, u6, 0x20);
  rows[3] = _mm256_permute2f128_ps(u3, u7, 0x20);
  rows[4] = _mm256_permute2f128_ps(u0, u4, 0x31);
  rows[5] = _mm256_permute2f128_ps(u1, u5, 0x31);
  rows[6] = _mm256_permute2f128_ps(u2, u6, 0x31);
  rows[7] = _mm256_permute2f128_ps(u3, u7, 0x31);
}

// Eight rays of eight floats, wherever they lie: one load each and a
// transpose. AVX2 gathers cost about a load per float (on AMD Zen 3 the eight
// gathers of a packet took 12 % of bench_moc's shadow rays, issue 44).
inline bool load_rays(const float* base, const std::int32_t* offset, Lanes* out) {
  __m256 rows[8];
  for (int k = 0; k < 8; ++k) rows[k] = _mm256_loadu_ps(base + offset[k]);
  transpose8(rows);
  for (int c = 0; c < 8; ++c) out[c] = rows[c];
  return true;
}

// SSE2's reductions over the two halves.
inline float reduce_min(Lanes x) {
  return packet_sse2::reduce_min({_mm256_castps256_ps128(x.v), _mm256_extractf128_ps(x.v, 1)});
}
inline float reduce_max(Lanes x) {
  return packet_sse2::reduce_max({_mm256_castps256_ps128(x.v), _mm256_extractf128_ps(x.v, 1)});
}

using SlotLanes = Lanes;
inline SlotLanes load_slots(const float* p) {
  return load(p);
}

#include "octree_lane_group_whole.inc"
#include "octree_lane_operators.inc"

}  // namespace packet_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx2")
namespace packet_avx2_wide {

// Thirty-two rays in four AVX2 registers, for batches whose rays stay
// together down the whole tree (one origin, targets adjacent in Morton
// order: a plan's candidate and its targets). Each node's bookkeeping (the
// stack, the child order, the interval test) is then paid once for 32 rays
// instead of 8: bench_plan's matrix took about 11 % less CPU than with 8
// lanes. Incoherent rays lose by it (lanes idle once their rays part), so
// only BatchOrder::kAsGiven batches use it (octree.hpp).
inline constexpr unsigned kLanes = 32;
inline constexpr int kRegisters = 4;

struct Lanes {
  __m256 r[kRegisters];
  Lanes() = default;
  Lanes(float x) {  // NOLINT: broadcast, implicit
    for (__m256& v : r) v = _mm256_set1_ps(x);
  }
};
// Register i holds lanes 8i .. 8i + 7, and a mask has them in those bits.
// (Plain loops over the registers: a lambda would not inherit the AVX2 target.)
inline Lanes load(const float* p) {
  Lanes out;
  for (int i = 0; i < kRegisters; ++i) out.r[i] = _mm256_load_ps(p + 8 * i);
  return out;
}
inline Lanes broadcast(float x) {
  return Lanes(x);
}
inline Lanes mul(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_mul_ps(x.r[i], y.r[i]);
  return x;
}
inline Lanes sub(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_sub_ps(x.r[i], y.r[i]);
  return x;
}
inline Lanes min(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_min_ps(x.r[i], y.r[i]);
  return x;
}
inline Lanes max(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_max_ps(x.r[i], y.r[i]);
  return x;
}
inline void store(float* p, Lanes x) {
  for (int i = 0; i < kRegisters; ++i) _mm256_store_ps(p + 8 * i, x.r[i]);
}
inline unsigned less_equal(Lanes x, Lanes y) {
  unsigned mask = 0;
  for (int i = 0; i < kRegisters; ++i) mask |= packet_avx2::less_equal(x.r[i], y.r[i]) << (8 * i);
  return mask;
}
inline unsigned less(Lanes x, Lanes y) {
  unsigned mask = 0;
  for (int i = 0; i < kRegisters; ++i) mask |= packet_avx2::less(x.r[i], y.r[i]) << (8 * i);
  return mask;
}
inline Lanes add(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_add_ps(x.r[i], y.r[i]);
  return x;
}
inline Lanes div(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_div_ps(x.r[i], y.r[i]);
  return x;
}
inline Lanes sqrt(Lanes x) {
  Lanes out;
  for (int i = 0; i < kRegisters; ++i) out.r[i] = _mm256_sqrt_ps(x.r[i]);
  return out;
}
inline Lanes bit_and(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_and_ps(x.r[i], y.r[i]);
  return x;
}
inline Lanes bit_or(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_or_ps(x.r[i], y.r[i]);
  return x;
}
inline Lanes bit_xor(Lanes x, Lanes y) {
  for (int i = 0; i < kRegisters; ++i) x.r[i] = _mm256_xor_ps(x.r[i], y.r[i]);
  return x;
}
inline Lanes select(unsigned mask, Lanes if_set, Lanes if_clear) {
  Lanes out;
  for (int i = 0; i < kRegisters; ++i) {
    out.r[i] = packet_avx2::select((mask >> (8 * i)) & 0xffu, if_set.r[i], if_clear.r[i]).v;
  }
  return out;
}
inline unsigned equal_ids(const std::uint32_t* ids, std::uint32_t id) {
  unsigned mask = 0;
  for (int i = 0; i < kRegisters; ++i) mask |= packet_avx2::equal_ids(ids + 8 * i, id) << (8 * i);
  return mask;
}

inline Lanes gather(const float* base, const std::int32_t* offset) {
  Lanes out;
  for (int i = 0; i < kRegisters; ++i) out.r[i] = packet_avx2::gather(base, offset + 8 * i).v;
  return out;
}

// Register i takes lanes 8i .. 8i + 7, loaded and transposed.
inline bool load_rays(const float* base, const std::int32_t* offset, Lanes* out) {
  for (int i = 0; i < kRegisters; ++i) {
    __m256 rows[8];
    for (int k = 0; k < 8; ++k) rows[k] = _mm256_loadu_ps(base + offset[8 * i + k]);
    packet_avx2::transpose8(rows);
    for (int c = 0; c < 8; ++c) out[c].r[i] = rows[c];
  }
  return true;
}

inline float reduce_min(Lanes x) {
  return packet_avx2::reduce_min(
      {_mm256_min_ps(_mm256_min_ps(x.r[0], x.r[1]), _mm256_min_ps(x.r[2], x.r[3]))});
}
inline float reduce_max(Lanes x) {
  return packet_avx2::reduce_max(
      {_mm256_max_ps(_mm256_max_ps(x.r[0], x.r[1]), _mm256_max_ps(x.r[2], x.r[3]))});
}

// A node's eight slots: AVX2's eight lanes.
using SlotLanes = packet_avx2::Lanes;
inline SlotLanes load_slots(const float* p) {
  return packet_avx2::load(p);
}

// A leaf tests its shapes one register (8 lanes) at a time and skips the
// registers with no lane in it: near its target a ray shares a leaf with few
// of its packet's rays (bench_plan: 6 lanes of 32 a leaf on average, in 2 of
// the 4 registers).
struct LaneGroup {
  using Lanes = packet_avx2::Lanes;
  static constexpr unsigned kLanes = packet_avx2::kLanes;
  static Lanes of(const packet_avx2_wide::Lanes& x, unsigned group) { return {x.r[group]}; }
  static Lanes load(const float* p) { return packet_avx2::load(p); }
  static void store(float* p, Lanes x) { packet_avx2::store(p, x); }
  static unsigned equal_ids(const std::uint32_t* ids, std::uint32_t id) {
    return packet_avx2::equal_ids(ids, id);
  }
};

#include "octree_lane_operators.inc"

}  // namespace packet_avx2_wide
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f")
namespace packet_avx512 {

inline constexpr unsigned kLanes = 16;

struct Lanes {
  __m512 v;
  Lanes() = default;
  Lanes(__m512 x) : v(x) {}                 // NOLINT: implicit
  Lanes(float x) : v(_mm512_set1_ps(x)) {}  // NOLINT: broadcast, implicit
};
inline Lanes load(const float* p) {
  return {_mm512_load_ps(p)};
}
inline Lanes broadcast(float x) {
  return Lanes(x);
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
inline unsigned less(Lanes x, Lanes y) {
  return static_cast<unsigned>(_mm512_cmp_ps_mask(x.v, y.v, _CMP_LT_OQ));
}
inline Lanes add(Lanes x, Lanes y) {
  return {_mm512_add_ps(x.v, y.v)};
}
inline Lanes div(Lanes x, Lanes y) {
  return {_mm512_div_ps(x.v, y.v)};
}
inline Lanes sqrt(Lanes x) {
  return {_mm512_sqrt_ps(x.v)};
}
// AVX512F has no float logic (that is AVX512DQ): through the integer view.
inline Lanes bit_and(Lanes x, Lanes y) {
  return {
      _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(x.v), _mm512_castps_si512(y.v)))};
}
inline Lanes bit_or(Lanes x, Lanes y) {
  return {_mm512_castsi512_ps(_mm512_or_si512(_mm512_castps_si512(x.v), _mm512_castps_si512(y.v)))};
}
inline Lanes bit_xor(Lanes x, Lanes y) {
  return {
      _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(x.v), _mm512_castps_si512(y.v)))};
}
inline Lanes select(unsigned mask, Lanes if_set, Lanes if_clear) {
  return {_mm512_mask_blend_ps(static_cast<__mmask16>(mask), if_clear.v, if_set.v)};
}
inline unsigned equal_ids(const std::uint32_t* ids, std::uint32_t id) {
  return static_cast<unsigned>(
      _mm512_cmpeq_epi32_mask(_mm512_loadu_si512(ids), _mm512_set1_epi32(static_cast<int>(id))));
}

inline Lanes gather(const float* base, const std::int32_t* offset) {
  return {_mm512_i32gather_ps(_mm512_load_si512(offset), base, 4)};
}

// Gathers do it here.
inline bool load_rays(const float*, const std::int32_t*, Lanes*) {
  return false;
}

inline float reduce_min(Lanes x) {
  return _mm512_reduce_min_ps(x.v);
}
inline float reduce_max(Lanes x) {
  return _mm512_reduce_max_ps(x.v);
}

// A node's eight slots fill half these lanes: AVX2's eight serve.
using SlotLanes = packet_avx2::Lanes;
inline SlotLanes load_slots(const float* p) {
  return packet_avx2::load(p);
}

#include "octree_lane_group_whole.inc"
#include "octree_lane_operators.inc"

}  // namespace packet_avx512
#pragma GCC pop_options

}  // namespace occlusion::octree_detail
