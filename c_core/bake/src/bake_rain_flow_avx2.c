/* The rain flow's vector kernels (bake_rain_flow_simd.h) for AVX2: four
 * texels per vector. Built with -mavx2 and -ffp-contract=off
 * (c_core/CMakeLists.txt) and called only where the CPU reports AVX2. */
#include "bake_rain_flow_rows.h"

#ifdef SOAK_BUILD_FLOW_AVX2

#include <immintrin.h>
#include <stdint.h>
#include <string.h>

int soak_rain_cpu_has_avx2(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
}

enum { L = 4 };
typedef __m256d V;
typedef __m128 F;
typedef __m256d M; /* all ones or all zeros per lane */
typedef __m256i I;

#define SIMD_FN(name) name##_avx2
#define V_ZERO() _mm256_setzero_pd()
#define V_SET1(a) _mm256_set1_pd(a)
#define V_LOAD(p) _mm256_loadu_pd(p)
#define V_STORE(p, v) _mm256_storeu_pd(p, v)
#define V_LOADF(p) _mm256_cvtps_pd(_mm_loadu_ps(p))
#define V_ADD _mm256_add_pd
#define V_SUB _mm256_sub_pd
#define V_MUL _mm256_mul_pd
#define V_DIV _mm256_div_pd
#define V_MAX _mm256_max_pd
#define V_MIN _mm256_min_pd
#define V_KEEP(v, m) _mm256_and_pd(v, m)
#define V_SELECT(m, a, b) _mm256_blendv_pd(b, a, m)
#define F_ZERO() _mm_setzero_ps()
#define F_STORE(p, f) _mm_storeu_ps(p, f)
#define F_FROM_V(v) _mm256_cvtpd_ps(v)
#define V_FROM_F(f) _mm256_cvtps_pd(f)
#define M_GT(a, b) _mm256_cmp_pd(a, b, _CMP_GT_OQ)
#define M_LT(a, b) _mm256_cmp_pd(a, b, _CMP_LT_OQ)
#define M_AND _mm256_and_pd
#define M_ANDNOT(a, b) _mm256_andnot_pd(a, b) /* b and not a */
#define M_ANY(m) (_mm256_movemask_pd(m) != 0)
#define M_NONZERO(p) _mm256_castsi256_pd(_mm256_cmpgt_epi64(I_BYTES(p), _mm256_setzero_si256()))
#define M_BIT(flags, d) bit_mask(flags, d)

/* Four bytes (per-texel flags) as four 64-bit lanes. */
static inline I I_BYTES(const unsigned char *p)
{
    int32_t v;
    memcpy(&v, p, sizeof v);
    return _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(v));
}

/* All ones in the lanes whose flags have bit d. */
static inline M bit_mask(I flags, int d)
{
    I bit = _mm256_set1_epi64x(1LL << d);
    return _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(flags, bit), bit));
}

static inline int all_ones(const unsigned char *p)
{
    uint32_t v;
    memcpy(&v, p, sizeof v);
    return v == UINT32_MAX;
}

#include "bake_rain_flow_simd.h"

#endif
