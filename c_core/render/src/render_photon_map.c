/* The volume photon map's storage (render_photons.c traces the photons):
 * a hash grid with cells of the gather radius, photons sorted by cell, and
 * the gather of J&C 1998 eq. 8 around a scattering vertex.
 *
 * Near the surface the gather sphere reaches out of the medium, where no
 * photon can be: dividing by the whole sphere's volume there under-counts
 * the density (by half at the surface). A dense medium stores its photons
 * within a few free paths of the surface, where the camera's vertices are
 * too, so this was most of the caustic's loss: 19 % at a radius of one mean
 * free path in test_render_caustics' slab. The gather divides by the part of
 * the sphere below the entry face's plane instead (the boundary correction
 * of kernel density estimation by renormalising the kernel over the
 * domain; exact in volume for a flat face, a first-order estimate of the
 * local density as the sphere's centroid moves below x). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render_photon_map.h"

static uint32_t cell_hash(int64_t x, int64_t y, int64_t z, size_t mask)
{
    uint64_t h = (uint64_t)x * 73856093ull ^ (uint64_t)y * 19349663ull ^ (uint64_t)z * 83492791ull;
    h ^= h >> 29;
    return (uint32_t)(h & mask);
}

static void cell_of(const rt_photon_map *m, soak_vec3 x, int64_t c[3])
{
    c[0] = (int64_t)floor(x.x / m->radius);
    c[1] = (int64_t)floor(x.y / m->radius);
    c[2] = (int64_t)floor(x.z / m->radius);
}

soak_status rt_photon_map_store(rt_photon_map *map, const rt_photon *photons, size_t n)
{
    if (n == 0) return SOAK_OK;
    size_t cells = 1;
    while (cells < 2 * n) cells *= 2;
    map->n_cells = cells;
    map->cell_start = calloc(cells + 1, sizeof(uint32_t));
    map->photons = malloc(n * sizeof(rt_photon));
    uint32_t *slot = malloc(n * sizeof(uint32_t));
    if (!map->cell_start || !map->photons || !slot || n >= 0xFFFFFFFFu) {
        free(slot);
        rt_photons_free(map);
        return SOAK_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; ++i) {
        int64_t cc[3];
        cell_of(map, soak_v3(photons[i].pos[0], photons[i].pos[1], photons[i].pos[2]), cc);
        slot[i] = cell_hash(cc[0], cc[1], cc[2], cells - 1);
        map->cell_start[slot[i] + 1]++;
    }
    for (size_t k = 0; k < cells; ++k) map->cell_start[k + 1] += map->cell_start[k];
    uint32_t *fill = calloc(cells, sizeof(uint32_t));
    if (!fill) {
        free(slot);
        rt_photons_free(map);
        return SOAK_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; ++i) map->photons[map->cell_start[slot[i]] + fill[slot[i]]++] = photons[i];
    map->n = n;
    free(fill);
    free(slot);
    return SOAK_OK;
}

void rt_photons_free(rt_photon_map *map)
{
    free(map->photons);
    free(map->cell_start);
    memset(map, 0, sizeof *map);
}

double rt_sphere_volume_below(double r, double depth)
{
    double full = 4.0 / 3.0 * SOAK_PI * r * r * r;
    if (!(depth < r)) return full;                       /* also INFINITY */
    double h = r - rt_max(0.0, depth);                   /* height of the cap above the plane */
    return full - SOAK_PI * h * h * (3.0 * r - h) / 3.0; /* sphere minus its cap */
}

soak_rgb rt_photons_gather(const rt_photon_map *map, soak_vec3 x, soak_vec3 d_in, const soak_hg2 *phase, unsigned obj,
                           double depth)
{
    soak_rgb sum = soak_rgb3(0, 0, 0);
    if (!map || map->n == 0) return sum;
    int64_t c[3];
    cell_of(map, x, c);
    uint32_t seen[27];
    int n_seen = 0;
    double r2 = map->radius * map->radius;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                uint32_t h = cell_hash(c[0] + dx, c[1] + dy, c[2] + dz, map->n_cells - 1);
                int dup = 0;
                for (int k = 0; k < n_seen && !dup; ++k) dup = seen[k] == h;
                if (dup) continue; /* two neighbour cells hashed to one bucket */
                seen[n_seen++] = h;
                for (uint32_t i = map->cell_start[h]; i < map->cell_start[h + 1]; ++i) {
                    const rt_photon *p = &map->photons[i];
                    if (p->object_id != obj) continue;
                    double ex = p->pos[0] - x.x, ey = p->pos[1] - x.y, ez = p->pos[2] - x.z;
                    if (ex * ex + ey * ey + ez * ez > r2) continue;
                    /* Light propagating along w_p scattered into -d_in (toward the camera). */
                    double cosang = -(p->dir[0] * d_in.x + p->dir[1] * d_in.y + p->dir[2] * d_in.z);
                    double ph = rt_hg2(phase, cosang);
                    sum.r += ph * p->power[0];
                    sum.g += ph * p->power[1];
                    sum.b += ph * p->power[2];
                }
            }
    return soak_rgb_scale(sum, 1.0 / rt_sphere_volume_below(map->radius, depth));
}
