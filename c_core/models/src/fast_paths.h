/* Bodies of the unchecked per-sample paths of film-ctx and ww-triace, as
 * static inline functions over constants made once at set-up: soak_model_eval
 * (models.c) compiles them into its own body (no call, no copy of the two
 * directions by value), and the public raw functions (soak_film_ctx_brdf_raw,
 * soak_ww_eval_triace_raw) make the constants and run the same bodies, so
 * every caller gets the same bits. Private to the models layer. */
#ifndef SOAK_MODELS_FAST_PATHS_H
#define SOAK_MODELS_FAST_PATHS_H

#include <math.h>

#include "soak/film.h"
#include "soak/vec.h"
#include "soak/ww.h"

/* The film BRDF's per-sample constants (soak_film_ctx_brdf_raw), made once
 * from a valid context and base albedo A: scale = A / (pi n^2 (1 - A Q)). */
typedef struct film_fast {
    double n, inv_n2, tau, scale;
    int interface; /* n != 1 */
} film_fast;

static inline film_fast film_fast_make(const soak_film_ctx *ctx, double base_albedo)
{
    film_fast f = {ctx->n, 1.0 / (ctx->n * ctx->n), ctx->tau,
                   base_albedo * SOAK_INV_PI / (ctx->n * ctx->n * (1.0 - base_albedo * ctx->ret)), ctx->n != 1.0};
    return f;
}

/* 1 - F of light from air at cos_i in (0, 1] and the refracted cosine: the
 * dielectric Fresnel of soak_fresnel_dielectric_raw without its branches,
 * since from air into n >= 1 there is no total internal reflection
 * (sin^2 t = (1 - cos_i^2) / n^2 < 1). */
static inline double film_transmit(const film_fast *f, double cos_i, double *cos_t)
{
    if (!f->interface) {
        *cos_t = cos_i;
        return 1.0;
    }
    double ct = sqrt(1.0 - (1.0 - cos_i * cos_i) * f->inv_n2), nct = f->n * ct, nc = f->n * cos_i;
    *cos_t = ct;
    double rs = (cos_i - nct) / (cos_i + nct), rp = (nc - ct) / (nc + ct);
    double R = 0.5 * (rs * rs + rp * rp);
    return 1.0 - (R > 1.0 ? 1.0 : R);
}

/* (1 - F_i) (1 - F_o) exp(-tau / cos_ti) exp(-tau / cos_to) A / (pi n^2 (1 - A Q)),
 * the two absorptions as one exp (each term may be +Inf, never NaN). */
static inline double film_brdf_fast(const film_fast *f, soak_vec3 wi, soak_vec3 wo)
{
    double cti, cto;
    double ti = film_transmit(f, wi.z < 1.0 ? wi.z : 1.0, &cti);
    double to = film_transmit(f, wo.z < 1.0 ? wo.z : 1.0, &cto);
    double att = f->tau > 0.0 ? exp(-(f->tau / cti + f->tau / cto)) : 1.0;
    return ti * to * att * f->scale;
}

/* [Lag13], refract_1_33: fit of (eta cos_i - cos_t) for eta = 1/1.33 on cos_i in [0, 1]. */
#define R133_ETA 0.7518796992481203 /* 1 / 1.33 */
#define R133_C0 (-0.666308423880957)
#define R133_C1 0.7518796992481197
#define R133_C2 (-0.34853799144237796)

/* The Tri-Ace BRDF's per-sample constants (soak_ww_eval_triace_raw):
 * spec = (1 - R0_top) / n^2 F_bottom alpha^2 / (2 pi), diffuse = (1 - R0_top) / n^2 diffuse. */
typedef struct triace_fast {
    double a2, one_minus_a2, alpha_prime, spec, diffuse;
} triace_fast;

static inline triace_fast triace_fast_make(const soak_ww_triace *t)
{
    double k = (1.0 - t->r0_top) * t->inv_n2;
    triace_fast f = {t->alpha2, 1.0 - t->alpha2, t->alpha_prime, k * t->fbottom * t->alpha2 * (0.5 * SOAK_INV_PI),
                     k * t->diffuse};
    return f;
}

/* Upward unit direction in the water for an air direction w (z > 0): the
 * reverse of refract_1_33(-w, +z), renormalised; xy2 = w.x^2 + w.y^2. */
static inline soak_vec3 triace_refract_up(soak_vec3 w, double xy2)
{
    double c = w.z;
    double z = R133_ETA * c - ((R133_C2 * c + R133_C1) * c + R133_C0);
    double inv = 1.0 / sqrt(R133_ETA * R133_ETA * xy2 + z * z), s = R133_ETA * inv;
    return soak_v3(w.x * s, w.y * s, z * inv);
}

/* soak_ww_eval_triace_raw (soak/ww.h):
 *   f = (1 - R0_top) (1 - (1 - cos_i)^5) a_lin / n^2 (F_bottom D G2 / (4 cos_i' cos_o') + diffuse),
 * with GGX D of h' = a + b unnormalised, D = a2 |h|^4 / (pi (hx^2 + hy^2 + a2 hz^2)^2),
 * and the height-correlated G2 / (4 cos cos) = 0.5 / (r_i cos_o' + r_o cos_i'),
 * r = sqrt(a2 + (1 - a2) cos'^2): one division for D and G2 together. */
static inline double triace_eval_fast(const triace_fast *f, soak_vec3 wi, double wi_xy2, soak_vec3 wo, double wo_xy2)
{
    soak_vec3 a = triace_refract_up(wi, wi_xy2), b = triace_refract_up(wo, wo_xy2);
    double hx = a.x + b.x, hy = a.y + b.y, hz = a.z + b.z;
    double hs = hx * hx + hy * hy, hz2 = hz * hz;
    double num = hs + hz2, den = hs + f->a2 * hz2;
    double ri = sqrt(f->a2 + f->one_minus_a2 * (a.z * a.z));
    double ro = sqrt(f->a2 + f->one_minus_a2 * (b.z * b.z));
    double spec = f->spec * (num * num) / (den * den * (ri * b.z + ro * a.z));

    /* Schlick T12 at the air side (no total internal reflection going in). */
    double m = 1.0 - wi.z, m2 = m * m;
    double ab = 1.0 - f->alpha_prime * (a.z + b.z) / (a.z * b.z);
    if (ab < 0.0) ab = 0.0;
    return (1.0 - m2 * m2 * m) * ab * (spec + f->diffuse);
}

#endif
