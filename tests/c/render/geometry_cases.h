/* Helpers the geometry tests share. */
#ifndef SOAK_TEST_GEOMETRY_CASES_H
#define SOAK_TEST_GEOMETRY_CASES_H

#include <math.h>

#include "soak/geometry.h"

/* A ray from o along d over (0, infinity). */
static inline soak_ray geo_ray(soak_vec3 o, soak_vec3 d)
{
    soak_ray r = {o, d, 0.0, INFINITY};
    return r;
}

/* Knuth's MMIX linear congruential step; a uniform number in [0, 1). */
static inline double geo_lcg01(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* A direction uniform on the sphere. */
static inline soak_vec3 geo_unit_dir(unsigned long long *s)
{
    double z = 1 - 2 * geo_lcg01(s), phi = 6.283185307179586 * geo_lcg01(s), r = sqrt(fmax(0.0, 1 - z * z));
    return soak_v3(r * cos(phi), r * sin(phi), z);
}

#endif
