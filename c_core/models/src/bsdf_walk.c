/* The traced layer (soak/bsdf.h, SOAK_BSDF_WALK): a smooth liquid film of
 * index n2 over an opaque base, followed bounce by bounce (Lekner & Dorf
 * 1988 as used in [JLD99] sec. 2.1 / 3.1). Reflect at the film top with
 * probability F12(cos1) (delta lobe); otherwise refract in, scatter off the
 * base, and at the underside leave with probability 1 - F21 or go back down
 * (total internal reflection beyond the critical angle).
 *
 * Radiance across the interface: entering multiplies radiance by 1/n^2,
 * leaving by n^2 (radiance / n^2 is invariant; the corrected factor of
 * [JLD99] Eq. 1/2, see soak/jensen.h). The two cancel for a path that
 * leaves, so the walk's weights carry neither, and light_at_base() carries
 * the 1/n^2 of light arriving inside: the base receives
 * E = (1 - F12(cos1)) L cos1 dw1 from a light seen at cos1 in air and sends
 * f_base E back, so
 *   f = f_base(w2_light, up) (1 - F12) e^{-a h / cos2} / n2^2
 * per bounce, and the exit density in air solid angle is
 *   pdf = pdf_base(w2) (1 - F21(cos2)) cos1 / (n2^2 cos2),
 * the Jacobian of Snell's map dw2/dw1 = (n1/n2)^2 cos1/cos2.
 *
 * The estimators (pbrt-v4's LayeredBxDF, Pharr, Jakob & Humphreys, PBR 4th
 * ed. sec. 14.3.2, for a specular top): eval sums over the bounces of one
 * walk from wo the light term toward wi, taking the top's transmission
 * 1 - F12(cos_o) and the underside's reflection F21 as weights instead of
 * choices; pdf sums the exit densities of the bounces of an independent walk
 * weighted by the probability of reaching them; both end by Russian roulette
 * once their weight has fallen below the first bounce's. sample plays the
 * choices (the walk the path tracer used to follow itself). */
#include <string.h>

#include "bsdf_internal.h"
#include "soak/rng.h"

#define WALK_MAX_BOUNCES 256 /* a bright base under total internal reflection: 1 - F21 caps the mean length */
#define STREAM_F 1
#define STREAM_PDF 2
#define STREAM_SAMPLE 3

static int absorbing(const soak_bsdf *b)
{
    soak_rgb a = b->d.film_absorption;
    return b->d.film_thickness > 0 && (a.r > 0 || a.g > 0 || a.b > 0);
}

static soak_rgb leg(const soak_bsdf *b, double cos)
{
    return absorbing(b) ? bsdf_film_absorb(b, cos) : soak_rgb3(1, 1, 1);
}

static double rgb_peak(soak_rgb c) { return fmax(c.r, fmax(c.g, c.b)); }

static uint64_t bits_of(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* SplitMix64's finaliser (Steele, Lea & Flood 2014), chained over the bits. */
static uint64_t mix64(uint64_t h, uint64_t x)
{
    uint64_t z = h ^ (x + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2));
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

uint64_t bsdf_walk_key(soak_vec3 wi, soak_vec3 wo)
{
    double v[6] = {wi.x, wi.y, wi.z, wo.x, wo.y, wo.z};
    uint64_t h = 0x5eed0f11f0ull;
    for (int i = 0; i < 6; ++i) h = mix64(h, bits_of(v[i]));
    return h;
}

/* The direction in the film toward wo (refracted), 0 when wo is below. */
static int enter(const soak_bsdf *b, soak_vec3 wo, double *T, soak_vec3 *up)
{
    double n2 = b->d.film_ior, cos2;
    if (!(wo.z > 0)) return 0;
    *T = 1.0 - bsdf_fresnel(wo.z, n2, &cos2);
    *up = soak_v3(wo.x / n2, wo.y / n2, cos2);
    return cos2 > 0;
}

/* Light arriving from wi (air, wi.z > 0) scattered by the base toward up. */
static void light_at_base(const soak_bsdf *b, soak_vec3 up, soak_vec3 wi, soak_rgb *f, double *pdf)
{
    double n2 = b->d.film_ior, cos2;
    *f = soak_rgb3(0, 0, 0);
    *pdf = 0;
    double T = 1.0 - bsdf_fresnel(wi.z, n2, &cos2);
    if (!(T > 0 && cos2 > 0)) return;
    soak_vec3 l2 = soak_v3(wi.x / n2, wi.y / n2, cos2);
    soak_rgb fb;
    double pb;
    if (b->base->eval(b, l2, up, &fb, &pb) != SOAK_OK) return;
    *f = soak_rgb_mul(soak_rgb_scale(fb, T / (n2 * n2)), leg(b, cos2));
    *pdf = pb * T * wi.z / (n2 * n2 * cos2);
}

/* One base scattering from up: the direction back up in the film (z > 0),
 * its weight f cos / pdf and its underside reflectance F21. */
static int scatter(const soak_bsdf *b, soak_vec3 up, soak_rng *rng, soak_bsdf_sample *bs, double *F21)
{
    double u[3] = {soak_rng_uniform(rng), soak_rng_uniform(rng), soak_rng_uniform(rng)};
    int ok = 0;
    memset(bs, 0, sizeof *bs);
    if (b->base->sample(b, up, u, bs, &ok) != SOAK_OK || !ok || !(bs->wi.z > 0)) return 0;
    *F21 = bsdf_fresnel(bs->wi.z, 1.0 / b->d.film_ior, NULL);
    return 1;
}

/* Russian roulette on a weight against the first bounce's: 0 ends the walk. */
static int survive(double w, double w0, soak_rng *rng, double *scale)
{
    double q = w0 > 0 ? fmin(1.0, w / w0) : 0.0;
    *scale = 1.0;
    if (q >= 1.0) return 1;
    if (!(q > 0) || soak_rng_uniform(rng) >= q) return 0;
    *scale = 1.0 / q;
    return 1;
}

static soak_rgb walk_f(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rng *rng)
{
    soak_rgb f = soak_rgb3(0, 0, 0);
    double T, F21, scale;
    soak_vec3 up;
    if (!(wi.z > 0) || !enter(b, wo, &T, &up)) return f;
    soak_rgb beta = soak_rgb_scale(leg(b, up.z), T);
    double beta0 = rgb_peak(beta);
    for (int bounce = 0; bounce < WALK_MAX_BOUNCES; ++bounce) {
        soak_rgb fl;
        double pl;
        light_at_base(b, up, wi, &fl, &pl);
        f = soak_rgb_add(f, soak_rgb_mul(beta, fl));
        soak_bsdf_sample bs;
        if (!scatter(b, up, rng, &bs, &F21)) break;
        soak_rgb there_and_back = soak_rgb_mul(leg(b, bs.wi.z), leg(b, bs.wi.z));
        beta = soak_rgb_scale(soak_rgb_mul(beta, soak_rgb_mul(bs.weight, there_and_back)), F21);
        if (!survive(rgb_peak(beta), beta0, rng, &scale)) break;
        beta = soak_rgb_scale(beta, scale);
        up = bsdf_mirror(bs.wi);
    }
    return f;
}

static double walk_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rng *rng)
{
    double T, F21, scale, pdf = 0;
    soak_vec3 up;
    if (!(wi.z > 0) || !enter(b, wo, &T, &up)) return 0;
    double q = T; /* probability of the walk reaching this bounce */
    for (int bounce = 0; bounce < WALK_MAX_BOUNCES; ++bounce) {
        soak_rgb fl;
        double pl;
        light_at_base(b, up, wi, &fl, &pl);
        pdf += q * pl;
        soak_bsdf_sample bs;
        if (!scatter(b, up, rng, &bs, &F21)) break;
        q *= F21;
        if (!survive(q, T, rng, &scale)) break;
        q *= scale;
        up = bsdf_mirror(bs.wi);
    }
    return pdf;
}

static soak_status walk_eval_keyed(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, uint64_t key, soak_rgb *f,
                                   double *pdf)
{
    soak_rng rng;
    soak_rng_seed(&rng, key, STREAM_F);
    *f = walk_f(b, wi, wo, &rng);
    soak_rng_seed(&rng, key, STREAM_PDF);
    *pdf = walk_pdf(b, wi, wo, &rng);
    return SOAK_OK;
}

static soak_status walk_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    return walk_eval_keyed(b, wi, wo, bsdf_walk_key(wi, wo), f, pdf);
}

static double walk_pdf_hashed(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    soak_rng rng;
    soak_rng_seed(&rng, bsdf_walk_key(wi, wo), STREAM_PDF);
    return walk_pdf(b, wi, wo, &rng);
}

/* The top's mirror: chosen with probability F12(cos_o), weight 1. */
static void top_mirror(soak_vec3 wo, soak_bsdf_sample *s)
{
    s->wi = bsdf_mirror(wo);
    s->weight = soak_rgb3(1, 1, 1);
    s->pdf = 0;
    s->delta = 1;
}

/* Leaving the film from wi (z > 0 inside) into air. */
static soak_vec3 leave(const soak_bsdf *b, soak_vec3 wi)
{
    double n2 = b->d.film_ior, cos_air = sqrt(fmax(0.0, 1.0 - n2 * n2 * (1.0 - wi.z * wi.z)));
    return soak_v3_norm(soak_v3(wi.x * n2, wi.y * n2, cos_air));
}

static soak_status walk_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    double T, F21;
    soak_vec3 up;
    *ok = 0;
    if (!enter(b, wo, &T, &up)) return SOAK_OK;
    if (u[0] >= T) {
        top_mirror(wo, s);
        *ok = 1;
        return SOAK_OK;
    }
    soak_rng rng;
    soak_rng_seed(&rng, mix64(bsdf_walk_key(soak_v3(u[0], u[1], u[2]), wo), 0), STREAM_SAMPLE);
    double ub[3] = {fmin(u[0] / T, 1.0 - 1e-16), u[1], u[2]}; /* the first bounce keeps the caller's numbers */
    soak_rgb beta = leg(b, up.z);
    for (int bounce = 0; bounce < WALK_MAX_BOUNCES; ++bounce) {
        soak_bsdf_sample bs = {.eta = 1};
        int got = 0;
        if (bounce == 0) {
            if (b->base->sample(b, up, ub, &bs, &got) != SOAK_OK || !got || !(bs.wi.z > 0)) return SOAK_OK;
            F21 = bsdf_fresnel(bs.wi.z, 1.0 / b->d.film_ior, NULL);
        } else if (!scatter(b, up, &rng, &bs, &F21)) {
            return SOAK_OK;
        }
        beta = soak_rgb_mul(beta, soak_rgb_mul(bs.weight, leg(b, bs.wi.z))); /* the way up */
        if (soak_rng_uniform(&rng) < F21) {
            beta = soak_rgb_mul(beta, leg(b, bs.wi.z)); /* back down, scattered up again next */
            up = bsdf_mirror(bs.wi);
            continue;
        }
        s->wi = leave(b, bs.wi);
        s->weight = beta;
        s->pdf = walk_pdf_hashed(b, s->wi, wo);
        s->delta = 0;
        *ok = s->pdf > 0;
        return SOAK_OK;
    }
    return SOAK_OK;
}

/* The base under the film: its index relative to the liquid. */
static soak_status walk_setup(soak_bsdf *b)
{
    double n2 = b->d.film_ior;
    b->d.eta = soak_rgb_scale(b->d.eta, 1.0 / n2);
    b->d.k = soak_rgb_scale(b->d.k, 1.0 / n2);
    if (b->d.kind == SOAK_BSDF_COATED) bsdf_coated_tables(b); /* the interface is now material/liquid */
    b->flags |= SOAK_BSDF_WALK;
    return SOAK_OK;
}

const soak_bsdf_ops bsdf_walk_ops = {walk_setup, walk_eval, walk_pdf_hashed, walk_sample, walk_eval_keyed};
