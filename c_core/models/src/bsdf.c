/* BSDF set-up and dispatch over the adaptors (soak/bsdf.h). */
#include <string.h>

#include "bsdf_internal.h"
#include "soak/ggx.h"

void soak_bsdf_desc_default(soak_bsdf_desc *d, soak_bsdf_kind kind)
{
    memset(d, 0, sizeof *d);
    d->kind = kind;
    d->albedo = soak_rgb3(0.5, 0.5, 0.5);
    d->eta = soak_rgb3(1.5, 1.5, 1.5);
    d->alpha = 0.1;
    d->ior = 1.5;
    d->coat_weight = 1.0;
    d->film_ior = 1.0;
    for (int ch = 0; ch < 3; ++ch) soak_model_params_default(&d->params[ch]);
}

static soak_status film_check(const soak_bsdf_desc *d)
{
    if (!soak_in_range(d->film_ior, 1, 3) || !soak_in_range(d->film_thickness, 0, 1e3)) return SOAK_ERR_ARG;
    for (int ch = 0; ch < 3; ++ch)
        if (!soak_in_range(soak_rgb_at(d->film_absorption, ch), 0, 1e9)) return SOAK_ERR_ARG;
    if (d->film_ior == 1.0) return SOAK_OK;
    return d->kind == SOAK_BSDF_LAMBERT || d->kind == SOAK_BSDF_GGX_CONDUCTOR || d->kind == SOAK_BSDF_GGX_DIELECTRIC ||
                   d->kind == SOAK_BSDF_COATED
               ? SOAK_OK
               : SOAK_ERR_ARG; /* glass and the models carry their own interfaces */
}

/* The kinds' tables, in soak_bsdf_kind order (GGX_CONDUCTOR and
 * GGX_DIELECTRIC share one adaptor). */
static const soak_bsdf_ops *const kind_ops[] = {&bsdf_lambert_ops, &bsdf_ggx_ops, &bsdf_ggx_ops,
                                                &bsdf_glass_ops,   &bsdf_model_ops, &bsdf_coated_ops};

/* A film over the base: closed form over Lambert when it applies, else the
 * traced layer. */
static soak_status layer_setup(soak_bsdf *b)
{
    b->flags |= SOAK_BSDF_DELTA;
    if (b->d.kind == SOAK_BSDF_LAMBERT && !b->d.film_traced && bsdf_film_ops.setup(b) == SOAK_OK) {
        b->ops = &bsdf_film_ops;
        return SOAK_OK;
    }
    b->ops = &bsdf_walk_ops;
    return b->ops->setup(b);
}

soak_status soak_bsdf_setup(const soak_bsdf_desc *d, soak_bsdf *b)
{
    if (!d || !b) return SOAK_ERR_NULL;
    if (!((int)d->kind >= 0 && (size_t)d->kind < sizeof kind_ops / sizeof kind_ops[0])) return SOAK_ERR_ARG;
    memset(b, 0, sizeof *b);
    b->d = *d;
    b->ops = b->base = kind_ops[d->kind];
    soak_status st = film_check(d);
    if (st == SOAK_OK) st = b->base->setup(b);
    if (st == SOAK_OK && d->film_ior > 1.0) st = layer_setup(b);
    return st;
}

int soak_bsdf_get_flags(const soak_bsdf *b) { return b ? b->flags : 0; }

/* What every eval and sample asks of its arguments. */
static soak_status check_pair(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    if (!b || !b->ops) return SOAK_ERR_NULL;
    return soak_v3_is_unit(wi) && soak_v3_is_unit(wo) ? SOAK_OK : SOAK_ERR_ARG;
}

/* The adaptors' outputs are finite by construction (test_bsdf, test_stability
 * check it for every kind); re-checked per call only in debug builds. */
#ifdef NDEBUG
#define BSDF_RECHECK(ok) ((void)0)
#else
static int finite_rgb(soak_rgb c) { return soak_is_finite(c.r) && soak_is_finite(c.g) && soak_is_finite(c.b); }
#define BSDF_RECHECK(ok)                      \
    do {                                      \
        if (!(ok)) return SOAK_ERR_NUMERIC;   \
    } while (0)
#endif

soak_status soak_bsdf_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    soak_status st = check_pair(b, wi, wo);
    if (st != SOAK_OK) return st;
    soak_rgb fv;
    double pv;
    if (!f) {
        pv = b->ops->pdf(b, wi, wo);
    } else {
        st = b->ops->eval(b, wi, wo, &fv, &pv);
        if (st != SOAK_OK) return st;
        BSDF_RECHECK(finite_rgb(fv));
        *f = fv;
    }
    BSDF_RECHECK(soak_is_finite(pv));
    if (pdf) *pdf = pv;
    return SOAK_OK;
}

soak_status soak_bsdf_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, double *pdf)
{
    if (!pdf) return SOAK_ERR_NULL;
    return soak_bsdf_eval(b, wi, wo, NULL, pdf);
}

soak_status soak_bsdf_sample_dir(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    if (!b || !b->ops || !u || !s || !ok) return SOAK_ERR_NULL;
    if (!soak_v3_is_unit(wo)) return SOAK_ERR_ARG;
    for (int i = 0; i < 3; ++i)
        if (!soak_in_range(u[i], 0, 1)) return SOAK_ERR_ARG;
    soak_bsdf_sample sv = {.eta = 1.0};
    int got = 0;
    /* only a two-sided BSDF (glass) is sampled from below */
    if ((b->flags & SOAK_BSDF_TRANSMIT) || wo.z > 0) {
        soak_status st = b->ops->sample(b, wo, u, &sv, &got);
        if (st != SOAK_OK) return st;
    }
    if (got) BSDF_RECHECK(finite_rgb(sv.weight) && soak_is_finite(sv.pdf));
    *s = sv;
    *ok = got;
    return SOAK_OK;
}

/* n estimates from streams key(wi, wo) + seed + i; Welford's running variance. */
static soak_status mean_of_estimates(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, long n, uint64_t seed,
                                     soak_rgb *mean, soak_rgb *se, double *pdf_mean)
{
    double m[3] = {0, 0, 0}, m2[3] = {0, 0, 0}, pdf, pdf_sum = 0;
    uint64_t key = bsdf_walk_key(wi, wo) + seed * 0x9e3779b97f4a7c15ull;
    for (long i = 0; i < n; ++i) {
        soak_rgb f;
        soak_status st = b->ops->eval_keyed(b, wi, wo, key + (uint64_t)i, &f, &pdf);
        if (st != SOAK_OK) return st;
        pdf_sum += pdf;
        for (int ch = 0; ch < 3; ++ch) {
            double x = soak_rgb_at(f, ch), d = x - m[ch];
            m[ch] += d / (double)(i + 1);
            m2[ch] += d * (x - m[ch]);
        }
    }
    for (int ch = 0; ch < 3; ++ch) {
        soak_rgb_set(mean, ch, m[ch]);
        soak_rgb_set(se, ch, n > 1 ? sqrt(m2[ch] / (double)(n - 1) / (double)n) : 0.0);
    }
    *pdf_mean = pdf_sum / (double)n;
    return SOAK_OK;
}

soak_status soak_bsdf_eval_mean(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, long n, uint64_t seed, soak_rgb *f,
                                soak_rgb *se, double *pdf)
{
    soak_status st = check_pair(b, wi, wo);
    if (st != SOAK_OK) return st;
    if (!f) return SOAK_ERR_NULL;
    if (!(n >= 1 && n <= 1000000000L)) return SOAK_ERR_ARG;
    soak_rgb mv = soak_rgb3(0, 0, 0), sv = mv;
    double pv = 0;
    if (b->ops->eval_keyed) st = mean_of_estimates(b, wi, wo, n, seed, &mv, &sv, &pv);
    else st = soak_bsdf_eval(b, wi, wo, &mv, &pv);
    if (st != SOAK_OK) return st;
    BSDF_RECHECK(finite_rgb(mv) && finite_rgb(sv) && soak_is_finite(pv));
    *f = mv;
    if (se) *se = sv;
    if (pdf) *pdf = pv;
    return SOAK_OK;
}
