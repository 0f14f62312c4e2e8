/* The rain bake's surface in UV space (soak/bake_rain.h step 1), made by
 * bake_rain_raster.c under the rules of soak/bake_uv.h; private to the
 * bake layer. */
#ifndef SOAK_BAKE_RAIN_SURFACE_H
#define SOAK_BAKE_RAIN_SURFACE_H

#include "soak/bake_uv.h"
#include "soak/geometry.h"
#include "soak/vec.h"

typedef struct rain_surface {
    int w, h;
    int *tri;          /* per texel, -1 = empty */
    double *pos;       /* 3 per texel */
    float *nrm;        /* 3 per texel */
    float *dpdx, *dpdy;/* 3 per texel: world step of one texel in +x, +y (image rows down) */
    float *area;       /* world area of the texel */
    double *level;     /* p.up */
    unsigned char *adj;/* bit d: neighbour d is 3D-adjacent and covered */
    float *drip;       /* > 0: level drop toward the open edge the water drips off */
    double mean_texel; /* mean sqrt(area) of covered texels */
} rain_surface;

/* Fills tri, pos, nrm, dpdx, dpdy, area and level of s (allocated, w x h)
 * from the faces of m and counts what happened to them. SOAK_ERR_ARG with
 * err when o refuses faces outside [0, 1]^2 and there are some. */
soak_status soak_rain_rasterise(const soak_mesh *m, const soak_uv_options *o, rain_surface *s, soak_vec3 up,
                                soak_uv_stats *stats, char *err, size_t errlen);

/* The mesh a rain bake takes: triangles, indices in range, finite
 * positions, UVs finite and within +-1e6 (SOAK_ERR_ARG with err). */
soak_status soak_rain_check_mesh(const soak_mesh *m, char *err, size_t errlen);

#endif
