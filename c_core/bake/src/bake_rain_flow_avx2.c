/* AVX2 kernels of the rain flow sweep (bake_rain_flow_rows.h): four texels
 * per instruction, each lane doing what texel_flux and texel_gather in
 * bake_rain_flow.c do, in the same order, so the bits are the same. What
 * makes that hold:
 * - add, sub, mul, div and the double <-> float conversions are IEEE
 *   operations rounded to nearest in both; this file is compiled with AVX2
 *   only, not FMA, and C11 mode keeps GCC from contracting;
 * - max_pd(a, b) and min_pd(a, b) are exactly a > b ? a : b and
 *   a < b ? a : b, the portable code's comparisons;
 * - where the portable code skips a term (a direction without a level drop,
 *   a neighbour that does not send) the lane computes +0 or is masked to +0,
 *   and adding +0 to a sum that is >= +0 changes no bit;
 * - lanes the portable code leaves early (uncovered, dry, facing down) are
 *   computed with the rest and then replaced by what it writes.
 * Built only for x86-64 with -mavx2 (c_core/CMakeLists.txt). */
#include "bake_rain_flow_rows.h"

#ifdef SOAK_RAIN_FLOW_AVX2

#include <immintrin.h>
#include <string.h>

int soak_rain_cpu_has_avx2(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
}

/* Four bytes (per-texel flags) as four 64-bit lanes. */
static __m256i bytes4(const unsigned char *p)
{
    int v;
    memcpy(&v, p, sizeof v);
    return _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(v));
}

/* All ones in the lanes whose flags have bit d. */
static __m256d bit_mask(__m256i flags, int d)
{
    __m256i bit = _mm256_set1_epi64x(1LL << d);
    return _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(flags, bit), bit));
}

static __m256d gt(__m256d a, __m256d b)
{
    return _mm256_cmp_pd(a, b, _CMP_GT_OQ);
}

static __m256d float4(const float *p)
{
    return _mm256_cvtps_pd(_mm_loadu_ps(p));
}

/* The outflows of texels x .. x + 3 of row y (texel_flux). */
static void flux4(const flow_job *j, const flux_row_ptrs *row, int x, int y)
{
    const soak_rain_flow_grid *g = j->g;
    size_t i = (size_t)y * g->w + x;
    const __m256d zero = _mm256_setzero_pd();
    __m256d covered = _mm256_castsi256_pd(_mm256_cmpgt_epi64(bytes4(g->covered + i), _mm256_setzero_si256()));
    __m256d h = _mm256_loadu_pd(j->depth + i), mobile = _mm256_sub_pd(h, _mm256_loadu_pd(g->retain + i));
    __m256d wet = _mm256_and_pd(covered, gt(mobile, zero));
    if (_mm256_movemask_pd(wet) == 0) { /* nothing moves (dry or uncovered): the common case, cheaply */
        for (int d = 0; d < 8; ++d) _mm_storeu_ps(row->o[d] + x, _mm_setzero_ps());
        _mm256_storeu_pd(row->out + x, zero);
        return;
    }
    __m256d drip = float4(g->drip + i);
    __m256d down = _mm256_and_pd(wet, _mm256_cmp_pd(drip, zero, _CMP_LT_OQ));
    __m256i adj = bytes4(g->adj + i);
    __m256d lvl = _mm256_loadu_pd(j->lvl + i), diff[9], sum = zero, mx = zero;
    for (int d = 0; d < 8; ++d) {
        __m256d dl = _mm256_sub_pd(lvl, _mm256_loadu_pd(j->lvl + (ptrdiff_t)i + j->step[d]));
        diff[d] = _mm256_and_pd(_mm256_max_pd(dl, zero), bit_mask(adj, d));
    }
    diff[8] = _mm256_and_pd(gt(drip, zero), _mm256_add_pd(h, drip));
    for (int d = 0; d < 9; ++d) {
        sum = _mm256_add_pd(sum, diff[d]);
        mx = _mm256_max_pd(diff[d], mx);
    }
    __m256d active = _mm256_andnot_pd(down, _mm256_and_pd(wet, gt(sum, zero)));
    __m256d moved = _mm256_min_pd(_mm256_mul_pd(_mm256_set1_pd(0.5), mx), mobile), out = zero;
    for (int d = 0; d < 9; ++d) {
        __m128 o = _mm_setzero_ps();
        if (_mm256_movemask_pd(_mm256_and_pd(active, gt(diff[d], zero)))) /* else every lane sends +0 */
            o = _mm256_cvtpd_ps(_mm256_and_pd(_mm256_div_pd(_mm256_mul_pd(moved, diff[d]), sum), active));
        if (d < 8) _mm_storeu_ps(row->o[d] + x, o);
        out = _mm256_add_pd(out, _mm256_cvtps_pd(o));
    }
    out = _mm256_blendv_pd(out, _mm256_cvtps_pd(_mm256_cvtpd_ps(mobile)), down);
    _mm256_storeu_pd(row->out + x, out);
}

int soak_rain_flux_row_avx2(const flow_job *j, const flux_row_ptrs *row, int y, int x0)
{
    int x = x0;
    for (; x + 4 <= j->g->w; x += 4) flux4(j, row, x, y);
    return x;
}

/* The new depths of texels x .. x + 3 of row y (texel_gather). */
static void gather4(const flow_job *j, const flux_row_ptrs fr[3], const float *const ar[3], int x, int y)
{
    static const int DX[8] = {1, 1, 0, -1, -1, -1, 0, 1}, DY[8] = {0, -1, -1, -1, 0, 1, 1, 1};
    const soak_rain_flow_grid *g = j->g;
    size_t i = (size_t)y * g->w + x;
    const __m256d zero = _mm256_setzero_pd();
    __m256d covered = _mm256_castsi256_pd(_mm256_cmpgt_epi64(bytes4(g->covered + i), _mm256_setzero_si256()));
    __m256d depth = _mm256_loadu_pd(j->depth + i);
    if (_mm256_movemask_pd(covered) == 0) {
        _mm256_storeu_pd(j->next + i, depth);
        _mm256_storeu_pd(j->lvl_next + i, zero);
        return;
    }
    __m256i pulls = bytes4(j->pulls + i);
    __m256d vol_in = zero;
    for (int d = 0; d < 8; ++d) {
        __m256d pulled = bit_mask(pulls, d);
        if (_mm256_movemask_pd(pulled) == 0) continue;
        int r = DY[d] + 1, kx = x + DX[d];
        __m256d sent = _mm256_mul_pd(float4(fr[r].o[(d + 4) & 7] + kx), float4(ar[r] + kx));
        vol_in = _mm256_add_pd(vol_in, _mm256_and_pd(sent, pulled));
    }
    __m256d h = _mm256_add_pd(_mm256_sub_pd(depth, _mm256_loadu_pd(fr[1].out + x)),
                              _mm256_div_pd(vol_in, float4(g->area + i)));
    __m256d next = _mm256_max_pd(h, zero);
    __m256d lvl = _mm256_add_pd(_mm256_loadu_pd(g->level + i), next);
    _mm256_storeu_pd(j->next + i, _mm256_blendv_pd(depth, next, covered));
    _mm256_storeu_pd(j->lvl_next + i, _mm256_and_pd(lvl, covered));
}

int soak_rain_gather_row_avx2(const flow_job *j, const flux_row_ptrs fr[3], const float *const ar[3], int y, int x0)
{
    int x = x0;
    for (; x + 5 <= j->g->w; x += 4) gather4(j, fr, ar, x, y); /* reads texels x - 1 .. x + 4 */
    return x;
}

#endif
