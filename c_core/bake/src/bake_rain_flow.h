/* Downhill flow of the rain bake (soak/bake_rain.h, step 3), private to the
 * bake layer and exposed to white-box tests.
 *
 * One routing sweep is a Jacobi update: every texel's outflows are computed
 * from the depths before the sweep, then every texel's depth becomes
 * depth - its outflow + the inflows its neighbours send it. The sweep here is
 * one pass in the pull form: a band of rows first computes, for its rows and
 * one row either side, each texel's moved volume, level-drop sum and total
 * outflow (3 doubles, kept in per-thread scratch), then every texel gathers
 * its inflows by recomputing the one outflow each neighbour sends it. The
 * arithmetic and its order are those of the two-pass scheme that stores nine
 * outflows per texel, so results are bitwise the same at any thread count. */
#ifndef SOAK_BAKE_RAIN_FLOW_H
#define SOAK_BAKE_RAIN_FLOW_H

#include "soak/bake.h"
#include "soak/status.h"

/* Neighbour d of texel (x, y) is (x + DX[d], y + DY[d]); (d + 4) & 7 is the
 * way back. */
extern const int SOAK_RAIN_DX[8];
extern const int SOAK_RAIN_DY[8];

typedef struct soak_rain_flow_grid {
    int w, h;
    const unsigned char *covered; /* 1: a triangle covers the texel */
    const unsigned char *adj;     /* bit d: neighbour d is 3D-adjacent and covered */
    const float *area;            /* world area of the texel */
    const float *drip;            /* > 0: level drop toward an open edge; < 0: faces down */
    const double *level;          /* p.up */
    const double *retain;         /* film depth kept */
} soak_rain_flow_grid;

/* iterations sweeps on depth (w * h, metres); scratch is allocated inside. */
soak_status soak_rain_flow(const soak_rain_flow_grid *g, double *depth, int iterations, const soak_bake_exec *exec,
                           double progress_lo, double progress_hi);

#endif
