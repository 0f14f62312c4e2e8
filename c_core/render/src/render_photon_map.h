/* The caustic photon map: storage and gather (render_photon_map.c). */
#ifndef SOAK_RENDER_PHOTON_MAP_H
#define SOAK_RENDER_PHOTON_MAP_H

#include "rt_ctx.h"

typedef struct rt_photon {
    float pos[3];
    float dir[3];   /* propagation direction before the scattering event */
    float power[3]; /* flux scattered at the event */
    unsigned object_id;
} rt_photon;

typedef struct rt_photon_map {
    rt_photon *photons; /* sorted by hash cell */
    size_t n;
    uint32_t *cell_start; /* n_cells + 1 */
    size_t n_cells;       /* power of two */
    double radius;
    long long emitted;
} rt_photon_map;

void rt_photons_free(rt_photon_map *map);
/* Stores n photons (copied) into map's hash grid; map->radius already set. */
soak_status rt_photon_map_store(rt_photon_map *map, const rt_photon *photons, size_t n);
/* sigma_s L_s estimate: sum over photons of object obj within the radius of
 * p(cos) * power / V, cos between the photon's propagation and the reverse of
 * the camera path direction d_in; V the part of the gather sphere below a
 * flat surface at distance depth above x (the whole sphere, 4/3 pi r^3, for
 * depth >= r or INFINITY: no surface known). */
soak_rgb rt_photons_gather(const rt_photon_map *map, soak_vec3 x, soak_vec3 d_in, const soak_hg2 *phase, unsigned obj,
                           double depth);
/* Volume of the sphere of radius r below a plane at distance depth above its
 * centre (depth clamped to [0, r]). */
double rt_sphere_volume_below(double r, double depth);

#endif
