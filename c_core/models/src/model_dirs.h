/* Direction checks shared by the BRDF models (ggx.c, ww.c, porous.c,
 * porous_ggx.c): unit vectors in the local frame within SOAK_GGX_UNIT_TOL
 * (1e-6, the tolerance their headers document), renormalised before use. */
#ifndef SOAK_MODEL_DIRS_H
#define SOAK_MODEL_DIRS_H

#include <math.h>

#include "soak/ggx.h"
#include "soak/status.h"
#include "soak/vec.h"

/* Unit within tolerance and finite (each component in [-2, 2] rules out
 * NaN and Inf before the length test); on success *out is renormalised. */
static inline int model_unit_ok(soak_vec3 v, soak_vec3 *out)
{
    if (!soak_v3_is_unit(v)) return 0;
    double l2 = soak_v3_dot(v, v);
    *out = soak_v3_scale(v, 1.0 / sqrt(l2));
    return 1;
}

/* As model_unit_ok, and in the upper hemisphere (z > 0). */
static inline int model_upper_unit_ok(soak_vec3 v, soak_vec3 *out)
{
    return model_unit_ok(v, out) && out->z > 0.0;
}

/* Polar angle from +z of a unit vector. */
static inline double model_theta(soak_vec3 v)
{
    return atan2(sqrt(v.x * v.x + v.y * v.y), v.z);
}

#endif
