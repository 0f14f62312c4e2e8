/* Directional albedo and cost of a scene material as the renderer shades it
 * (soak/accuracy.h). */
#define _POSIX_C_SOURCE 200809L
#include "soak/accuracy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rt_ctx.h"
#include "render_bsdfs.h"
#include "scene_levels.h"
#include "soak/bsdf.h"
#include "soak/rng.h"

#define COST_PAIRS 64

int soak_accuracy_supported(const soak_material *m)
{
    if (!m) return 0;
    if (m->type == SOAK_MAT_LAMBERT || m->type == SOAK_MAT_CONDUCTOR || m->type == SOAK_MAT_MODEL) return 1;
    return m->type == SOAK_MAT_WET && m->base != SOAK_BASE_MEDIUM;
}

/* The renderer's BSDFs of one material: rt_bsdfs_setup reads only the
 * materials of the scene it is given. */
static soak_status material_bsdfs(const soak_material *m, int trace_films, rt_material_bsdf *out)
{
    if (!soak_accuracy_supported(m)) return SOAK_ERR_UNSUPPORTED;
    soak_scene one;
    memset(&one, 0, sizeof one);
    one.materials = (soak_material *)m;
    one.n_materials = 1;
    return rt_bsdfs_setup(&one, trace_films, out, NULL, 0);
}

/* f cos / pdf of one sampled direction (0 when none). */
static soak_rgb sample_once(const soak_bsdf *b, soak_vec3 wo, soak_rng *rng)
{
    double u[3] = {soak_rng_uniform(rng), soak_rng_uniform(rng), soak_rng_uniform(rng)};
    soak_bsdf_sample s;
    int ok = 0;
    if (soak_bsdf_sample_dir(b, wo, u, &s, &ok) != SOAK_OK || !ok || !(s.wi.z > 0)) return soak_rgb3(0, 0, 0);
    return s.weight;
}

static void bsdf_albedo(const soak_bsdf *b, soak_vec3 wo, int samples, soak_rng *rng, soak_rgb *mean, soak_rgb *var)
{
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
    for (int i = 0; i < samples; ++i) {
        soak_rgb x = sample_once(b, wo, rng);
        for (int ch = 0; ch < 3; ++ch) {
            double v = soak_rgb_at(x, ch);
            if (!isfinite(v)) v = 0; /* the renderer counts such paths black */
            sum[ch] += v;
            sum2[ch] += v * v;
        }
    }
    for (int ch = 0; ch < 3; ++ch) {
        double m = sum[ch] / samples;
        soak_rgb_set(mean, ch, m);
        soak_rgb_set(var, ch, samples > 1 ? fmax(sum2[ch] / samples - m * m, 0.0) / (samples - 1) : 0.0);
    }
}

/* The states a surface point is shaded in, with their probabilities, as
 * render_surface.c draws them: dry, the film with its thickness, the pore
 * water at zero thickness (a share film_pore_share of the wet draws). */
#define N_STATES 3
typedef struct state_mix {
    double p[N_STATES];
} state_mix;

static state_mix mix_of(const rt_material_bsdf *mb, const soak_material *m, double wetness)
{
    double p_wet = mb->has_wet ? wetness * m->film_coverage : 0.0;
    double pore = mb->has_pore ? p_wet * m->film_pore_share : 0.0;
    return (state_mix){{1.0 - p_wet, p_wet - pore, pore}};
}

static const soak_bsdf *state_bsdf(const rt_material_bsdf *mb, int state)
{
    return state == 0 ? &mb->dry : state == 1 ? &mb->wet : &mb->pore;
}

static soak_status albedo_of(const rt_material_bsdf *mb, state_mix mix, soak_vec3 wo, int samples, uint64_t seed,
                             soak_albedo_estimate *out);

soak_status soak_material_albedo(const soak_material *m, double wetness, double cos_o, int samples, uint64_t seed,
                                 int trace_films, soak_albedo_estimate *out)
{
    if (!m || !out) return SOAK_ERR_NULL;
    if (!soak_in_range(wetness, 0, 1) || !(cos_o > 0 && cos_o <= 1) || !(samples >= 1 && samples <= 100000000))
        return SOAK_ERR_ARG;
    rt_material_bsdf mb;
    soak_status st = material_bsdfs(m, trace_films, &mb);
    if (st != SOAK_OK) return st;
    soak_vec3 wo = soak_v3(sqrt(fmax(0.0, 1.0 - cos_o * cos_o)), 0.0, cos_o);
    return albedo_of(&mb, mix_of(&mb, m, wetness), wo, samples, seed, out);
}

/* Each state with its own stream (1 dry, 2 film, 3 pore water), so a
 * material without pores estimates as it did before they had a state. */
static soak_status albedo_of(const rt_material_bsdf *mb, state_mix mix, soak_vec3 wo, int samples, uint64_t seed,
                             soak_albedo_estimate *out)
{
    out->value = out->std_error = soak_rgb3(0, 0, 0);
    soak_rgb var = out->value;
    for (int i = 0; i < N_STATES; ++i) {
        double p = mix.p[i];
        if (!(p > 0)) continue;
        soak_rng rng;
        soak_rgb mean = soak_rgb3(0, 0, 0), v = mean;
        soak_rng_seed(&rng, seed, (uint64_t)i + 1);
        bsdf_albedo(state_bsdf(mb, i), wo, samples, &rng, &mean, &v);
        for (int ch = 0; ch < 3; ++ch) {
            soak_rgb_set(&out->value, ch, soak_rgb_at(out->value, ch) + p * soak_rgb_at(mean, ch));
            soak_rgb_set(&var, ch, soak_rgb_at(var, ch) + p * p * soak_rgb_at(v, ch));
        }
    }
    out->std_error = soak_rgb3(sqrt(var.r), sqrt(var.g), sqrt(var.b));
    return SOAK_OK;
}

/* f(wi, wo) cos(wi) of one BSDF (a traced film's: the mean of samples estimates). */
static soak_rgb direct(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, int samples, uint64_t seed)
{
    soak_rgb f = soak_rgb3(0, 0, 0);
    if (soak_bsdf_eval_mean(b, wi, wo, samples, seed, &f, NULL, NULL) != SOAK_OK) return soak_rgb3(0, 0, 0);
    return soak_rgb3(f.r * wi.z, f.g * wi.z, f.b * wi.z);
}

/* levels: a preset's BSDFs at its levels of liquid (scene_levels.h), as
 * the renderer sets them up (render_levels.c); n_levels = 0: none. */
struct soak_shading_material {
    const soak_material *m;
    rt_material_bsdf mb;
    int n_levels;
    rt_material_bsdf *levels;
};

static soak_status shading_levels(soak_shading_material *p)
{
    const soak_material_levels *L = p->m->levels;
    if (p->m->type != SOAK_MAT_WET || !L || L->n == 0) return SOAK_OK;
    p->levels = calloc((size_t)L->n, sizeof *p->levels);
    if (!p->levels) return SOAK_ERR_NOMEM;
    for (int i = 0; i < L->n; ++i) {
        soak_status st = rt_material_bsdf_setup(&L->view[i], 0, &p->levels[i]);
        if (st != SOAK_OK) return st;
    }
    p->n_levels = L->n;
    return SOAK_OK;
}

soak_status soak_shading_material_new(const soak_material *m, soak_shading_material **out)
{
    if (!m || !out) return SOAK_ERR_NULL;
    *out = NULL;
    soak_shading_material *p = calloc(1, sizeof *p);
    if (!p) return SOAK_ERR_NOMEM;
    p->m = m;
    soak_status st = material_bsdfs(m, 0, &p->mb);
    if (st == SOAK_OK) st = shading_levels(p);
    if (st != SOAK_OK) {
        soak_shading_material_free(p);
        return st;
    }
    *out = p;
    return SOAK_OK;
}

void soak_shading_material_free(soak_shading_material *p)
{
    if (!p) return;
    free(p->levels);
    free(p);
}

soak_status soak_material_radiance(const soak_material *m, double wetness, soak_vec3 wo, soak_rgb env,
                                   const soak_local_light *lights, int n_lights, int samples, uint64_t seed,
                                   soak_albedo_estimate *out)
{
    soak_shading_material *p = NULL;
    soak_status st = soak_shading_material_new(m, &p);
    if (st == SOAK_OK) st = soak_shading_radiance(p, wetness, wo, env, lights, n_lights, samples, seed, out);
    soak_shading_material_free(p);
    return st;
}

/* The direct light of the states in mix: sum of p f(wi, wo) cos(wi) E. */
static soak_rgb direct_mix(const rt_material_bsdf *mb, state_mix mix, int samples, uint64_t seed,
                           const soak_local_light *l, soak_vec3 wo)
{
    soak_rgb L = soak_rgb3(0, 0, 0);
    for (int i = 0; i < N_STATES; ++i) {
        if (!(mix.p[i] > 0)) continue;
        soak_rgb f = direct(state_bsdf(mb, i), l->wi, wo, samples, seed + (uint64_t)i);
        for (int ch = 0; ch < 3; ++ch)
            soak_rgb_set(&L, ch, soak_rgb_at(L, ch) + mix.p[i] * soak_rgb_at(f, ch) * soak_rgb_at(l->irradiance, ch));
    }
    return L;
}

/* The radiance of one material state (its BSDFs mb) in the mix of states
 * at wetness (film probability wetness * m's coverage). */
static soak_status state_radiance(const rt_material_bsdf *mb, const soak_material *m, double wetness, soak_vec3 wo,
                                  soak_rgb env, const soak_local_light *lights, int n_lights, int samples,
                                  uint64_t seed, soak_albedo_estimate *out)
{
    state_mix mix = mix_of(mb, m, wetness);
    soak_albedo_estimate a;
    soak_status st = albedo_of(mb, mix, wo, samples, seed, &a);
    if (st != SOAK_OK) return st;
    soak_rgb L = soak_rgb3(a.value.r * env.r, a.value.g * env.g, a.value.b * env.b);
    for (int i = 0; i < n_lights; ++i) {
        if (!soak_v3_is_unit(lights[i].wi) || !(lights[i].wi.z > 0)) continue;
        soak_rgb d = direct_mix(mb, mix, samples, seed, &lights[i], wo);
        L = soak_rgb3(L.r + d.r, L.g + d.g, L.b + d.b);
    }
    out->value = L;
    out->std_error = soak_rgb3(a.std_error.r * env.r, a.std_error.g * env.g, a.std_error.b * env.b);
    return SOAK_OK;
}

/* (1 - f) a + f b, the errors added in quadrature. */
static soak_albedo_estimate lerp_estimate(soak_albedo_estimate a, soak_albedo_estimate b, double f)
{
    soak_albedo_estimate r;
    for (int ch = 0; ch < 3; ++ch) {
        double ea = (1 - f) * soak_rgb_at(a.std_error, ch), eb = f * soak_rgb_at(b.std_error, ch);
        soak_rgb_set(&r.value, ch, (1 - f) * soak_rgb_at(a.value, ch) + f * soak_rgb_at(b.value, ch));
        soak_rgb_set(&r.std_error, ch, sqrt(ea * ea + eb * eb));
    }
    return r;
}

soak_status soak_shading_radiance(const soak_shading_material *p, double wetness, soak_vec3 wo, soak_rgb env,
                                  const soak_local_light *lights, int n_lights, int samples, uint64_t seed,
                                  soak_albedo_estimate *out)
{
    if (!p || !out || (!lights && n_lights > 0)) return SOAK_ERR_NULL;
    if (!soak_in_range(wetness, 0, 1) || !soak_v3_is_unit(wo) || !(wo.z > 0) || !(n_lights >= 0) ||
        !(samples >= 1 && samples <= 100000000))
        return SOAK_ERR_ARG;
    if (p->n_levels == 0) return state_radiance(&p->mb, p->m, wetness, wo, env, lights, n_lights, samples, seed, out);
    /* a preset's levels: the linear interpolation in the object wetness the
     * renderer's level draw has as its mean (render_levels.c) */
    const soak_material_levels *L = p->m->levels;
    double f, film = L->recipe.film_over ? wetness : 1.0;
    int i = scene_levels_find(L, wetness, &f);
    soak_albedo_estimate a, b;
    soak_status st = state_radiance(&p->levels[i], &L->view[i], film, wo, env, lights, n_lights, samples, seed, &a);
    if (st != SOAK_OK || !(f > 0)) {
        *out = a;
        return st;
    }
    st = state_radiance(&p->levels[i + 1], &L->view[i + 1], film, wo, env, lights, n_lights, samples, seed, &b);
    if (st == SOAK_OK) *out = lerp_estimate(a, b, f);
    return st;
}

static const soak_bsdf *shaded(const rt_material_bsdf *mb) { return mb->has_wet ? &mb->wet : &mb->dry; }

static double cpu_seconds(void) { return (double)clock() / CLOCKS_PER_SEC; }

soak_status soak_material_cost(const soak_material *m, int n_rounds, double *eval_ns, double *sample_ns)
{
    if (!m || !eval_ns || !sample_ns) return SOAK_ERR_NULL;
    if (!(n_rounds >= 1 && n_rounds <= 1000000)) return SOAK_ERR_ARG;
    rt_material_bsdf mb;
    soak_status st = material_bsdfs(m, 0, &mb);
    if (st != SOAK_OK) return st;
    const soak_bsdf *b = shaded(&mb);
    st = soak_bsdf_eval_cost_ns(b, n_rounds, eval_ns);
    if (st != SOAK_OK) return st;
    soak_rng rng;
    soak_rng_seed(&rng, 7, 0);
    soak_vec3 wo = soak_v3(0.5, 0.0, sqrt(0.75));
    volatile double sink = 0;
    long n = (long)n_rounds * COST_PAIRS;
    double t0 = cpu_seconds();
    for (long i = 0; i < n; ++i) {
        soak_rgb x = sample_once(b, wo, &rng);
        sink += x.g;
    }
    *sample_ns = (cpu_seconds() - t0) * 1e9 / (double)n;
    (void)sink;
    return SOAK_OK;
}

soak_status soak_material_eval_loop(const soak_material *m, long n, double *checksum)
{
    if (!m || !checksum) return SOAK_ERR_NULL;
    if (!(n >= 0 && n <= 1000000000L)) return SOAK_ERR_ARG;
    rt_material_bsdf mb;
    soak_status st = material_bsdfs(m, 0, &mb);
    if (st != SOAK_OK) return st;
    return soak_bsdf_eval_loop(shaded(&mb), n, checksum);
}

/* Preset and liquid names are [a-z0-9_-] (soak/preset.h): anything else
 * could not be one and must not reach the JSON text. */
static int plain_name(const char *s)
{
    if (!*s || strlen(s) >= 64) return 0;
    for (; *s; ++s)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= '0' && *s <= '9') || *s == '_' || *s == '-')) return 0;
    return 1;
}

soak_status soak_accuracy_preset_scene(const char *preset, const char *liquid, double wetness, soak_scene *scene,
                                       char *err, size_t errlen)
{
    if (!preset || !liquid || !scene) return SOAK_ERR_NULL;
    if (!soak_in_range(wetness, 0, 1) || !plain_name(preset) || !plain_name(liquid)) return SOAK_ERR_ARG;
    char text[1024];
    int n = snprintf(text, sizeof text,
                     "{\"render\": {\"width\": 4, \"height\": 4, \"spp\": 1, \"max_depth\": 8},"
                     " \"camera\": {\"position\": [0, 0, 2], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 30}, \"environment\": {\"type\": \"constant\", \"radiance\": [1, 1, 1]},"
                     " \"materials\": {\"m\": {\"type\": \"preset\", \"name\": \"%s\", \"liquid\": \"%s\", \"wetness\": %.17g}},"
                     " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\", \"wetness\": 1}]}",
                     preset, liquid, wetness);
    if (n < 0 || (size_t)n >= sizeof text) return SOAK_ERR_ARG;
    return soak_scene_parse(text, "report", ".", scene, err, errlen);
}
