/* The rain bake's surface sampled in UV space (soak/bake_rain.h step 1):
 * which triangle covers each texel (bake_rain_raster.c, under the rules of
 * soak/bake_uv.h), its point, normal, world steps and area, which neighbours
 * are adjacent in 3D, where water drips off and which way it runs
 * (bake_rain_surface.c). Private to the bake layer. */
#ifndef SOAK_BAKE_RAIN_SURFACE_H
#define SOAK_BAKE_RAIN_SURFACE_H

#include "soak/bake_rain.h"
#include "soak/bake_uv.h"
#include "soak/geometry.h"
#include "soak/vec.h"

typedef struct rain_surface {
    int w, h;
    int *tri;           /* per texel, -1 = empty */
    double *pos;        /* 3 per texel */
    float *nrm;         /* 3 per texel */
    float *dpdx, *dpdy; /* 3 per texel: world step of one texel in +x, +y (image rows down) */
    float *area;        /* world area of the texel */
    double *level;      /* p.up */
    unsigned char *adj; /* bit d: neighbour d is 3D-adjacent and covered */
    float *drip;        /* > 0: level drop toward the open edge the water drips off */
    float *descent;     /* 2 per texel: steepest descent, texels (x, y down) per metre; 0, 0 if level */
    double mean_texel;  /* mean sqrt(area) of covered texels */
} rain_surface;

/* Below this |tangential gravity| (sin of the slope) a texel is level: no
 * descent direction, the routing falls back to level drops. */
#define SOAK_RAIN_LEVEL_TOL 1e-6

static inline soak_vec3 soak_rain_vget(const double *a, size_t i)
{
    return soak_v3(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
}

static inline soak_vec3 soak_rain_fget(const float *a, size_t i)
{
    return soak_v3(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
}

/* The mesh a rain bake takes: triangles, indices in range, finite
 * positions, UVs finite and within +-1e6 (SOAK_ERR_ARG with err). */
soak_status soak_rain_check_mesh(const soak_mesh *m, char *err, size_t errlen);
/* Allocates the maps of a w x h surface; on error nothing is kept. */
soak_status soak_rain_surface_alloc(rain_surface *s, int w, int h);
void soak_rain_surface_free(rain_surface *s);
/* Fills tri, pos, nrm, dpdx, dpdy, area and level of s (allocated, w x h)
 * from the faces of m and counts what happened to them. SOAK_ERR_ARG with
 * err when o refuses faces outside [0, 1]^2 and there are some. */
soak_status soak_rain_rasterise(const soak_mesh *m, const soak_uv_options *o, rain_surface *s, soak_vec3 up,
                                soak_uv_stats *stats, char *err, size_t errlen);
/* Adjacency, drip edges, descent directions and the mean texel size of a
 * rasterised s. */
soak_status soak_rain_surface_connect(rain_surface *s, soak_vec3 up, const soak_bake_exec *exec);

#endif
