/* The texel grid the rain bake's water moves on (soak/bake_rain.h, step 3):
 * the eight neighbour steps and what routing reads of each texel, shared by
 * the sweeps (bake_rain_flow.c) and the streams (bake_rain_stream.c). */
#ifndef SOAK_BAKE_RAIN_GRID_H
#define SOAK_BAKE_RAIN_GRID_H

/* Neighbour d of texel (x, y) is (x + DX[d], y + DY[d]); (d + 4) & 7 is the
 * way back. */
#define SOAK_RAIN_DX_INIT                                                                                              \
    {                                                                                                                  \
        1, 1, 0, -1, -1, -1, 0, 1                                                                                      \
    }
#define SOAK_RAIN_DY_INIT                                                                                              \
    {                                                                                                                  \
        0, -1, -1, -1, 0, 1, 1, 1                                                                                      \
    }
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
    const float *descent;         /* 2 per texel, the steepest descent in texel steps (x right, y down) per
                                     metre run, (0, 0) where level; NULL: route by level drops only */
} soak_rain_flow_grid;

#endif
