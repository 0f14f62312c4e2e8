/* Row kernels of the rain flow sweep (bake_rain_flow.c), shared by the
 * portable code and the vector kernels (bake_rain_flow_simd.h, built for
 * AVX2 and AVX-512). Private to those files. */
#ifndef SOAK_BAKE_RAIN_FLOW_ROWS_H
#define SOAK_BAKE_RAIN_FLOW_ROWS_H

#include <stddef.h>

#include "bake_rain_grid.h"

/* What the texels of one row send: o[d][x] to neighbour d (float, as the
 * two-pass scheme stores it) and out[x], the sum of its nine outflows (drip
 * included) in that scheme's order. */
typedef struct flux_row_ptrs {
    float *o[8];
    double *out;
} flux_row_ptrs;

typedef struct flow_job flow_job;

/* A vector kernel does the texels [x0, returned x) of row y with the same
 * arithmetic in the same order as the portable texel functions, and leaves
 * the rest of the row to them. Its last vector may overlap the one before:
 * a texel's results depend only on the sweep's inputs, so writing them twice
 * writes the same bits. The gather reads one texel either side of those it
 * does. */
typedef int (*flux_row_fn)(const flow_job *j, const flux_row_ptrs *row, int y, int x0);
typedef int (*gather_row_fn)(const flow_job *j, const flux_row_ptrs fr[3], const float *const ar[3], int y, int x0);

/* One sweep's inputs and outputs. lvl and lvl_next (level + depth of each
 * covered texel, 0 elsewhere) have w + 1 zeros before and after the map, so
 * that a texel's eight neighbours can be loaded for any texel of the map
 * (several at a time by a vector kernel); adjacency masks decide what is
 * used. */
struct flow_job {
    const soak_rain_flow_grid *g;
    const double *depth;
    double *next;
    const double *lvl;
    double *lvl_next;
    const unsigned char *pulls; /* bit d: neighbour d exists and sends to this texel (its adj has the way back) */
    float *ring_o;              /* per thread: 3 rows (row y in slot y % 3) x 8 directions x w outflows */
    double *ring_out;           /* per thread: 3 rows x w total outflows */
    ptrdiff_t step[8];          /* index offset of neighbour d */
    flux_row_fn flux_row;       /* the vector kernels, or NULL: the portable code only */
    gather_row_fn gather_row;
};

/* Call these only where the CPU has the instructions (soak_rain_cpu_has_*). */
#ifdef SOAK_BUILD_FLOW_AVX2
int soak_rain_cpu_has_avx2(void);
int soak_rain_flux_row_avx2(const flow_job *j, const flux_row_ptrs *row, int y, int x0);
int soak_rain_gather_row_avx2(const flow_job *j, const flux_row_ptrs fr[3], const float *const ar[3], int y, int x0);
#endif
#ifdef SOAK_BUILD_FLOW_AVX512
int soak_rain_cpu_has_avx512(void);
int soak_rain_flux_row_avx512(const flow_job *j, const flux_row_ptrs *row, int y, int x0);
int soak_rain_gather_row_avx512(const flow_job *j, const flux_row_ptrs fr[3], const float *const ar[3], int y,
                                int x0);
#endif

#endif
