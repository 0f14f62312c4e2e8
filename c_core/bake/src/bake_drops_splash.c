/* Splashes of drops on wet texels (model and sources in soak/bake_drops.h). */
#include <math.h>

#include "soak/bake_drops.h"
#include "soak/bake_rain.h"
#include "soak/rng.h"

#define PI 3.14159265358979323846
#define SPLASH_STREAM 0x53504c415348ull /* "SPLASH": a stream apart from the impacts' */

double soak_splash_k(double d_mm, double v)
{
    if (!(d_mm > 0.0 && d_mm <= 1e3) || !(v > 0.0 && v < 1e3)) return 0.0;
    double d = d_mm * 1e-3, rho = SOAK_WATER_RHO, sigma = SOAK_WATER_SIGMA;
    double we = rho * v * v * d / sigma, oh = SOAK_RAIN_WATER_VISCOSITY / sqrt(rho * sigma * d);
    return we * pow(oh, -0.4);
}

double soak_splash_k_critical(double film_m, double d_mm)
{
    if (!(film_m > 0.0) || !(d_mm > 0.0 && d_mm < 1e3)) return 2100.0;
    double delta = film_m / (d_mm * 1e-3);
    delta = delta < 1.0 ? delta : 1.0;
    return 2100.0 + 5880.0 * pow(delta, 1.44);
}

int soak_splash_fingers(double d_mm, double v)
{
    if (!(d_mm > 0.0 && d_mm <= 1e3) || !(v > 0.0 && v < 1e3)) return 1;
    double d = d_mm * 1e-3, rho = SOAK_WATER_RHO;
    double we = rho * v * v * d / SOAK_WATER_SIGMA, re = rho * v * d / SOAK_RAIN_WATER_VISCOSITY;
    double n = floor(sqrt(we) * pow(re, 0.25) / (4.0 * sqrt(3.0)) + 0.5);
    return n < 1.0 ? 1 : (n > SOAK_SPLASH_MAX_FINGERS ? SOAK_SPLASH_MAX_FINGERS : (int)n);
}

int soak_splash_throw(const soak_drops_params *p, const soak_drop_impact *imp, double film_m,
                      soak_splash_drop out[SOAK_SPLASH_MAX_FINGERS])
{
    if (!p || !imp || !out || !p->splash || !(p->splash_fraction > 0.0) || !(film_m > 0.0)) return 0;
    double v = soak_drop_velocity(imp->d_mm);
    if (!(soak_splash_k(imp->d_mm, v) > soak_splash_k_critical(film_m, imp->d_mm))) return 0;
    int n = soak_splash_fingers(imp->d_mm, v);
    soak_rng rng;
    long slab = (long)floor(imp->t / SOAK_DROPS_SLAB);
    soak_rng_seed(&rng, soak_seed_derive(p->seed ^ SPLASH_STREAM, (uint64_t)slab),
                  (uint64_t)imp->cell << 32 | imp->index);
    double phase = 2.0 * PI * soak_rng_uniform(&rng), d_s = imp->d_mm * cbrt(p->splash_fraction / n);
    for (int k = 0; k < n; ++k) {
        double u = p->splash_speed * v * (0.5 + 0.5 * soak_rng_uniform(&rng));
        double r = u * u / SOAK_GRAVITY / p->texel_m, a = phase + 2.0 * PI * k / n;
        out[k].x = imp->x + r * cos(a), out[k].y = imp->y + r * sin(a);
        out[k].d_mm = d_s, out[k].v = u;
    }
    return n;
}
