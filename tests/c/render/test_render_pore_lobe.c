/* The reference renderer's preset surface at partial wetness, where the
 * film covers c of the surface and water fills the pores (p f) of the rest
 * (soak/wet_specular.h point 4): the material's own rough lobe stays in air
 * over ks (1 - c) of the point, as the chain's header and the front ends
 * have it, and the pore water is a flat liquid surface over the body alone.
 *
 * 1. Specular part (the body made black): the rendered directional albedo
 *    (soak_material_albedo, the renderer's own draws and sampling) equals
 *      ks (1 - c) E(mu) + (A - c) F(mu, n_liquid) + c Film(mu),
 *    A = c + (1 - c) p f the interface area, from the chain's numbers
 *    (soak_wetness_eval), E the grain lobe's albedo alone and Film the
 *    film over the grains, both traced photon by photon (soak measure
 *    --config coated, a second method), F Fresnel's formula. The old
 *    description (pore water over the grains, lobe ks (1 - A) in air) is
 *    computed too and must lie outside the tolerance: the check can fail.
 * 2. Whole material: the same sum with the body, each part traced: the dry
 *    part with the coat weight that puts ks (1 - c) of lobe in air,
 *    ks (1 - c) / (1 - A) (the areas' bookkeeping, not the renderer's
 *    function), the film over the coated body, the pore water over the
 *    bare body.
 * 3. White furnace: body albedo 1: directional albedo <= 1.
 * 4. Reciprocity where no film lies (c = 0: only the new dry and pore
 *    draws, both closed forms): f(a, b) = f(b, a).
 * Within 4 combined standard errors; green channel. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/accuracy.h"
#include "soak/fresnel.h"
#include "soak/measure.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/wetness.h"

#define SAMPLES 60000
#define PATHS 200000

typedef struct state {
    const char *preset;
    double wetness;
} state;

/* c > 0 (sand, brick at 0.5: pores full, part filmed) and c = 0 (sand at
 * 0.25, oak at 0.5: pores partly full, no film) */
static const state STATES[] = {{"sand", 0.5}, {"brick", 0.5}, {"sand", 0.25}, {"oak", 0.5}};

/* One traced stack: coat of weight coat over a body of albedo body, under
 * a film of the chain's liquid (thickness h, 0: the liquid's surface) or
 * in air (liquid 0). */
static soak_status traced(const soak_preset *p, const soak_wet_params *w, double coat, double body, int liquid, double h,
                          double mu, soak_measure_result *r)
{
    soak_measure_setup s;
    soak_measure_setup_default(&s);
    s.config = SOAK_MEASURE_COATED;
    s.cos_incidence = mu;
    s.base_albedo = body;
    s.coat_ior = p->ior;
    s.coat_alpha = w->ggx_alpha;
    s.coat_weight = coat;
    s.ior = liquid ? w->film_ior : 1.0;
    s.film_alpha = liquid ? w->film_absorption_per_m.g : 0.0;
    s.film_thickness = liquid ? h : 0.0;
    s.paths = PATHS;
    s.seed = 17;
    return soak_measure_run(&s, r);
}

typedef struct part {
    double v, se;
} part;

static part add(part a, double wa, part b, double wb)
{
    return (part){wa * a.v + wb * b.v, sqrt(wa * wa * a.se * a.se + wb * wb * b.se * b.se)};
}

static part run(const soak_preset *p, const soak_wet_params *w, double coat, double body, int liquid, double h, double mu,
                int *ok)
{
    soak_measure_result r;
    if (traced(p, w, coat, body, liquid, h, mu, &r) != SOAK_OK) *ok = 0;
    return *ok ? (part){r.value, r.std_error} : (part){0, 0};
}

static int rendered(soak_material *m, soak_rgb body, double mu, part *out)
{
    soak_albedo_estimate e;
    m->albedo = body;
    if (soak_material_albedo(m, 1.0, mu, SAMPLES, 11, 0, &e) != SOAK_OK) return 0;
    *out = (part){e.value.g, e.std_error.g};
    return 1;
}

static double z_of(part got, part want) { return (got.v - want.v) / sqrt(got.se * got.se + want.se * want.se); }

/* Checks 1 and 2 at one view cosine. */
static void check_parts(const state *s, const soak_preset *p, const soak_wet_params *w, soak_material *m, double mu)
{
    const double c = w->film_coverage, A = soak_wet_interface_area(w), ks = w->specular_weight;
    const double h = w->film ? w->film_thickness_m : 0.0, a = w->albedo_subsurface.g;
    int ok = 1;
    double F = 0;
    ok = soak_fresnel_dielectric(mu, w->film_ior, &F, NULL) == SOAK_OK;
    part lobe = run(p, w, 1.0, 0.0, 0, 0, mu, &ok), film = run(p, w, ks, 0.0, 1, h, mu, &ok);
    part grains_wet = run(p, w, ks, 0.0, 1, 0.0, mu, &ok), got = {0, 0};
    ok = ok && rendered(m, soak_rgb3(0, 0, 0), mu, &got);
    part want = add(add(lobe, ks * (1 - c), film, c), 1, (part){F, 0}, A - c);
    part old = add(add(lobe, ks * (1 - A), film, c), 1, grains_wet, A - c);
    double z = z_of(got, want), z_old = z_of(got, old);
    char what[300];
    printf("  %-6s w %.2f mu %.2f: c %.3f A %.3f ks %.3f | specular: rendered %.5f +- %.5f, "
           "ks(1-c)E + (A-c)F + c Film %.5f (z %+.2f), old ks(1-A)E %.5f (z %+.2f)\n",
           s->preset, s->wetness, mu, c, A, ks, got.v, got.se, want.v, z, old.v, z_old);
    snprintf(what, sizeof what, "%s w %.2f mu %.2f: specular part = ks(1-c) E + (A-c) F + c Film (|z| %.2f <= 4), "
             "old description excluded (|z| %.1f > 4)", s->preset, s->wetness, mu, z, z_old);
    check_true(what, ok && fabs(z) <= 4.0 && fabs(z_old) > 4.0);

    double k_dry = A < 1 ? fmin(1.0, ks * (1 - c) / (1 - A)) : ks;
    part dry = run(p, w, k_dry, a, 0, 0, mu, &ok), wet = run(p, w, ks, a, 1, h, mu, &ok);
    part pore = run(p, w, 0.0, a, 1, 0.0, mu, &ok);
    ok = ok && rendered(m, w->albedo_subsurface, mu, &got);
    want = add(add(dry, 1 - A, wet, c), 1, pore, A - c);
    z = z_of(got, want);
    printf("  %-6s w %.2f mu %.2f: whole: rendered %.5f +- %.5f, traced parts %.5f +- %.5f (dry coat %.3f), z %+.2f\n",
           s->preset, s->wetness, mu, got.v, got.se, want.v, want.se, k_dry, z);
    snprintf(what, sizeof what, "%s w %.2f mu %.2f: whole material = its three parts traced (|z| %.2f <= 4)", s->preset,
             s->wetness, mu, z);
    check_true(what, ok && fabs(z) <= 4.0);
}

static void check_furnace(const state *s, soak_material *m)
{
    static const double mus[4] = {1.0, 0.866, 0.5, 0.174};
    for (int i = 0; i < 4; ++i) {
        part got = {0, 0};
        int ok = rendered(m, soak_rgb3(1, 1, 1), mus[i], &got);
        char what[200];
        snprintf(what, sizeof what, "%s w %.2f mu %.3f: white body, albedo %.5f +- %.5f <= 1", s->preset, s->wetness,
                 mus[i], got.v, got.se);
        check_true(what, ok && got.v <= 1.0 + 4 * got.se);
    }
}

/* f(wi, wo) of the whole material from its one-light radiance (no sky). */
static double f_of(const soak_material *m, soak_vec3 wi, soak_vec3 wo, int *ok)
{
    soak_local_light l = {wi, soak_rgb3(1, 1, 1)};
    soak_albedo_estimate e;
    if (soak_material_radiance(m, 1.0, wo, soak_rgb3(0, 0, 0), &l, 1, 16, 3, &e) != SOAK_OK) *ok = 0;
    return e.value.g / wi.z;
}

static void check_reciprocity(const state *s, const soak_wet_params *w, soak_material *m)
{
    if (w->film_coverage > 0) return; /* the film's f is a walk's estimate (test_render_film_traced) */
    static const double th[4][2] = {{10, 50}, {30, 70}, {5, 85}, {60, 60}};
    m->albedo = w->albedo_subsurface;
    for (int i = 0; i < 4; ++i) {
        double a = th[i][0] * SOAK_PI / 180, b = th[i][1] * SOAK_PI / 180;
        soak_vec3 u = soak_v3(sin(a), 0, cos(a)), v = soak_v3(-sin(b) * cos(0.7), -sin(b) * sin(0.7), cos(b));
        int ok = 1;
        double fab = f_of(m, u, v, &ok), fba = f_of(m, v, u, &ok);
        char what[200];
        snprintf(what, sizeof what, "%s w %.2f: f(%g, %g deg) %.9f = f(%g, %g deg) %.9f", s->preset, s->wetness, th[i][0],
                 th[i][1], fab, th[i][1], th[i][0], fba);
        check_true(what, ok && fabs(fab - fba) <= 1e-9 * fmax(fab, 1e-3));
    }
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[512];
    if (!check_status("presets load", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    for (size_t i = 0; i < sizeof STATES / sizeof STATES[0]; ++i) {
        const state *s = &STATES[i];
        const soak_preset *p = soak_presets_find(db, s->preset);
        soak_wet_input in = p ? soak_wet_input_steady(p, s->wetness) : (soak_wet_input){0};
        soak_wet_params w;
        soak_scene scene;
        if (!check_true(s->preset, p && water && soak_wetness_eval(p, water, &in, &w) == SOAK_OK) ||
            !check_status("scene", soak_accuracy_preset_scene(s->preset, "water", s->wetness, &scene, err, sizeof err),
                          SOAK_OK))
            continue;
        check_true("a partial wetness: pore water, and a dry part left", w.water_specular_weight > 0 &&
                   soak_wet_interface_area(&w) < 1);
        check_parts(s, p, &w, &scene.materials[0], 1.0);
        check_parts(s, p, &w, &scene.materials[0], 0.5);
        check_furnace(s, &scene.materials[0]);
        check_reciprocity(s, &w, &scene.materials[0]);
        soak_scene_free(&scene);
    }
    soak_presets_free(db);
    return check_finish();
}
