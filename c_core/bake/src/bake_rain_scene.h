/* The rain bake's surface and sky exposure (soak/bake_rain.h steps 1-2),
 * made once for a frame sequence; private to the bake layer. */
#ifndef SOAK_BAKE_RAIN_SCENE_H
#define SOAK_BAKE_RAIN_SCENE_H

#include "bake_rain_runnels.h"
#include "soak/bake_rain.h"

typedef struct soak_rain_scene {
    int w, h;
    unsigned char *covered;         /* 1: a triangle covers the texel */
    unsigned char *adj;             /* bit d: neighbour d is 3D-adjacent and covered */
    float *area;                    /* world area of the texel */
    float *drip;                    /* > 0: level drop toward an open edge; < 0: faces down */
    double *level;                  /* p.up */
    float *descent;                 /* 2 per texel: steepest descent in texel steps */
    float *up_dot_n;                /* n.up (1 on uncovered texels) */
    soak_image exposure;            /* step 2 */
    soak_uv_stats uv;               /* step 1's faces (soak/bake_uv.h) */
    soak_rain_runnel_field runnels; /* step 3c (contact angle > 0 and the film on); else empty */
} soak_rain_scene;

/* Checks p, the size and the mesh as soak_bake_rain does (same errors). */
soak_status soak_rain_scene_build(const soak_mesh *mesh, int width, int height, const soak_rain_params *p,
                                  const soak_bake_exec *exec, soak_rain_scene *out, char *err, size_t errlen);
void soak_rain_scene_free(soak_rain_scene *sc);

/* The bake's gutter: `gutter` rings of uncovered texels take the mean of
 * their filled neighbours. */
soak_status soak_rain_dilate(float *img, const unsigned char *covered, int w, int h, int gutter,
                             const soak_bake_exec *exec);

#endif
