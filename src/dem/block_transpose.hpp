#pragma once
/// Data movement between the particle and bond rows (Vec3, BondStiffness: arrays of structures)
/// and the bond kernel's blocks of eight lanes (one array per component), done with AVX-512
/// shuffles in registers. The generic copies in bond_forces.cpp compile to one scalar load or
/// store per double plus the moves of each lane's index out of a vector register, which took more
/// time than the bond law itself (perf, 2026-12-05). These functions move the same numbers (the
/// only arithmetic, a row difference, is the same IEEE subtraction), so results are bit for bit
/// those of the generic copies. Compiled only where the target has AVX-512F and AVX-512VL.
#include <cstdint>

#include "bonds/bond_stiffness.hpp"
#include "core/vec3.hpp"

#if defined(__AVX512F__) && defined(__AVX512VL__)
#include <immintrin.h>
#define BPMKIT_BLOCK_TRANSPOSE 1

namespace bpm::block_transpose {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 rows are three packed doubles");
static_assert(sizeof(BondStiffness) == 4 * sizeof(double),
              "BondStiffness rows are four packed doubles");

using Components = double[3][8];

/// Row `index` of `rows` as (x, y, z, 0). The masked load reads nothing past the row, so the last
/// row of an array is safe.
inline __m256d row(const Vec3* rows, std::int32_t index) {
  return _mm256_maskz_loadu_pd(0x7, &rows[index].x);
}

/// Eight rows (x, y, z, -) into three component arrays (64-byte aligned).
inline void rows_to_components(const __m256d (&r)[8], Components& c) {
  // Rows k and k + 4 share a register: (x_k y_k z_k - | x_k+4 y_k+4 z_k+4 -).
  const __m512d p0 = _mm512_insertf64x4(_mm512_castpd256_pd512(r[0]), r[4], 1);
  const __m512d p1 = _mm512_insertf64x4(_mm512_castpd256_pd512(r[1]), r[5], 1);
  const __m512d p2 = _mm512_insertf64x4(_mm512_castpd256_pd512(r[2]), r[6], 1);
  const __m512d p3 = _mm512_insertf64x4(_mm512_castpd256_pd512(r[3]), r[7], 1);
  // Per 128-bit lane: lo = (x_a x_b | z_a z_b | x_a+4 x_b+4 | z_a+4 z_b+4), hi = the y's and
  // padding.
  const __m512d lo01 = _mm512_unpacklo_pd(p0, p1), hi01 = _mm512_unpackhi_pd(p0, p1);
  const __m512d lo23 = _mm512_unpacklo_pd(p2, p3), hi23 = _mm512_unpackhi_pd(p2, p3);
  const __m512i even = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13);
  const __m512i odd = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
  _mm512_store_pd(c[0], _mm512_permutex2var_pd(lo01, even, lo23));
  _mm512_store_pd(c[1], _mm512_permutex2var_pd(hi01, even, hi23));
  _mm512_store_pd(c[2], _mm512_permutex2var_pd(lo01, odd, lo23));
}

/// Eight consecutive Vec3 rows (24 doubles from `rows`) into three component arrays.
inline void aos_to_components(const Vec3* rows, Components& c) {
  const double* p = &rows->x;
  const __m512d m0 = _mm512_loadu_pd(p), m1 = _mm512_loadu_pd(p + 8), m2 = _mm512_loadu_pd(p + 16);
  // Component j of row k is double 3k + j: the first five rows lie in m0 and m1, the rest in m2.
  for (int j = 0; j < 3; ++j) {
    const __m512i first = _mm512_setr_epi64(j, j + 3, j + 6, j + 9, j + 12, j + 15, 0, 0);
    const __m512d head = _mm512_permutex2var_pd(m0, first, m1);  // rows 0-5 (row 5 only for j = 0)
    const __m512i rest = j == 0 ? _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 8 + 2, 8 + 5)
                                : _mm512_setr_epi64(0, 1, 2, 3, 4, 8 + j - 1, 8 + j + 2, 8 + j + 5);
    _mm512_store_pd(c[j], _mm512_permutex2var_pd(head, rest, m2));
  }
}

/// Three component arrays into eight consecutive Vec3 rows (24 doubles at `rows`).
inline void components_to_aos(const Components& c, Vec3* rows) {
  const __m512d x = _mm512_load_pd(c[0]), y = _mm512_load_pd(c[1]), z = _mm512_load_pd(c[2]);
  // Output double 3k + j is component j of row k. Each output register takes two of x, y, z first,
  // then the third (index 8 + lane) in its remaining slots.
  // m0 = x0 y0 z0 x1 y1 z1 x2 y2
  const __m512d xy0 = _mm512_permutex2var_pd(x, _mm512_setr_epi64(0, 8, 0, 1, 9, 0, 2, 10), y);
  const __m512d m0 = _mm512_permutex2var_pd(xy0, _mm512_setr_epi64(0, 1, 8, 3, 4, 9, 6, 7), z);
  // m1 = z2 x3 y3 z3 x4 y4 z4 x5
  const __m512d xy1 = _mm512_permutex2var_pd(x, _mm512_setr_epi64(0, 3, 11, 0, 4, 12, 0, 5), y);
  const __m512d m1 =
      _mm512_permutex2var_pd(xy1, _mm512_setr_epi64(8 + 2, 1, 2, 8 + 3, 4, 5, 8 + 4, 7), z);
  // m2 = y5 z5 x6 y6 z6 x7 y7 z7
  const __m512d xy2 = _mm512_permutex2var_pd(x, _mm512_setr_epi64(13, 0, 6, 14, 0, 7, 15, 0), y);
  const __m512d m2 =
      _mm512_permutex2var_pd(xy2, _mm512_setr_epi64(0, 8 + 5, 2, 3, 8 + 6, 5, 6, 8 + 7), z);
  double* p = &rows->x;
  _mm512_storeu_pd(p, m0);
  _mm512_storeu_pd(p + 8, m1);
  _mm512_storeu_pd(p + 16, m2);
}

/// Eight consecutive BondStiffness rows into the four stiffness arrays.
inline void stiffness_to_components(const BondStiffness* rows, double (&k_n)[8], double (&k_s)[8],
                                    double (&k_tor)[8], double (&k_ben)[8]) {
  const double* p = &rows->k_n;
  const __m512d m0 = _mm512_loadu_pd(p), m1 = _mm512_loadu_pd(p + 8);
  const __m512d m2 = _mm512_loadu_pd(p + 16), m3 = _mm512_loadu_pd(p + 24);
  // (a0 a1 a2 a3 b0 b1 b2 b3) for the components (a, b) = (k_n, k_s) and (k_tor, k_ben), rows 0-3
  // from m0 and m1, rows 4-7 from m2 and m3.
  const __m512i ns = _mm512_setr_epi64(0, 4, 8, 12, 1, 5, 9, 13);
  const __m512i tb = _mm512_setr_epi64(2, 6, 10, 14, 3, 7, 11, 15);
  const __m512d ns_low = _mm512_permutex2var_pd(m0, ns, m1),
                ns_high = _mm512_permutex2var_pd(m2, ns, m3);
  const __m512d tb_low = _mm512_permutex2var_pd(m0, tb, m1),
                tb_high = _mm512_permutex2var_pd(m2, tb, m3);
  _mm512_store_pd(k_n, _mm512_shuffle_f64x2(ns_low, ns_high, 0x44));  // low halves
  _mm512_store_pd(k_s, _mm512_shuffle_f64x2(ns_low, ns_high, 0xEE));  // high halves
  _mm512_store_pd(k_tor, _mm512_shuffle_f64x2(tb_low, tb_high, 0x44));
  _mm512_store_pd(k_ben, _mm512_shuffle_f64x2(tb_low, tb_high, 0xEE));
}

}  // namespace bpm::block_transpose

#endif
