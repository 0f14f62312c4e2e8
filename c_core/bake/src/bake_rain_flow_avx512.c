/* The rain flow's vector kernels (bake_rain_flow_simd.h) for AVX-512:
 * eight texels per vector, lane masks in mask registers. Built with
 * -mavx512f and -ffp-contract=off (c_core/CMakeLists.txt) and called only
 * where the CPU reports AVX-512F. */
#include "bake_rain_flow_rows.h"

#ifdef SOAK_BUILD_FLOW_AVX512

#include <immintrin.h>
#include <stdint.h>
#include <string.h>

int soak_rain_cpu_has_avx512(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") != 0;
}

enum { L = 8 };
typedef __m512d V;
typedef __m256 F;
typedef __mmask8 M;
typedef __m512i I;

#define SIMD_FN(name) name##_avx512
#define V_ZERO() _mm512_setzero_pd()
#define V_SET1(a) _mm512_set1_pd(a)
#define V_LOAD(p) _mm512_loadu_pd(p)
#define V_STORE(p, v) _mm512_storeu_pd(p, v)
#define V_LOADF(p) _mm512_cvtps_pd(_mm256_loadu_ps(p))
#define V_ADD _mm512_add_pd
#define V_SUB _mm512_sub_pd
#define V_MUL _mm512_mul_pd
#define V_DIV _mm512_div_pd
#define V_MAX _mm512_max_pd
#define V_MIN _mm512_min_pd
#define V_KEEP(v, m) _mm512_maskz_mov_pd(m, v)
#define V_SELECT(m, a, b) _mm512_mask_blend_pd(m, b, a)
#define F_ZERO() _mm256_setzero_ps()
#define F_STORE(p, f) _mm256_storeu_ps(p, f)
#define F_FROM_V(v) _mm512_cvtpd_ps(v)
#define V_FROM_F(f) _mm512_cvtps_pd(f)
#define M_GT(a, b) _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ)
#define M_LT(a, b) _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ)
#define M_AND(a, b) ((M)((a) & (b)))
#define M_ANDNOT(a, b) ((M)(~(a) & (b))) /* b and not a */
#define M_ANY(m) ((m) != 0)
#define M_NONZERO(p) _mm512_test_epi64_mask(I_BYTES(p), I_BYTES(p))
#define M_BIT(flags, d) _mm512_test_epi64_mask(flags, _mm512_set1_epi64(1LL << (d)))

/* Eight bytes (per-texel flags) as eight 64-bit lanes. */
static inline I I_BYTES(const unsigned char *p)
{
    int64_t v;
    memcpy(&v, p, sizeof v);
    return _mm512_cvtepu8_epi64(_mm_cvtsi64_si128(v));
}

static inline int all_ones(const unsigned char *p)
{
    uint64_t v;
    memcpy(&v, p, sizeof v);
    return v == UINT64_MAX;
}

#include "bake_rain_flow_simd.h"

#endif
