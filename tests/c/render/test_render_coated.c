/* The reference renderer's preset surface (the material's rough interface
 * over its body, soak/bsdf.h COATED, under the liquid's film when wet)
 * against the same stack traced photon by photon (soak measure --config
 * coated: a facet drawn per crossing, Fresnel and masking played, the film's
 * Fresnel and absorption along its legs; no tabulated albedo, no series).
 * For every opaque dielectric preset, dry (w = 0) and wet (w = 1, where the
 * film covers everything), at 0, 30, 60 and 80 degrees, green channel: the
 * renderer's directional albedo (soak_material_albedo: its own sampling, the
 * film's walk included) equals the measurement within 4 combined standard
 * errors. The interface's parameters come from the wetness chain
 * (soak_wetness_eval), not from the renderer's material. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/accuracy.h"
#include "soak/measure.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/wetness.h"

#define SAMPLES 60000
#define PATHS 200000

static soak_status measured(const soak_preset *p, const soak_wet_params *w, double cos_o, soak_measure_result *r)
{
    soak_measure_setup s;
    soak_measure_setup_default(&s);
    s.config = SOAK_MEASURE_COATED;
    s.cos_incidence = cos_o;
    s.base_albedo = w->albedo_subsurface.g;
    s.coat_ior = p->ior;
    s.coat_alpha = w->ggx_alpha;
    s.coat_weight = w->specular_weight;
    s.ior = w->film ? w->film_ior : 1.0;
    s.film_alpha = w->film ? w->film_absorption_per_m.g : 0.0;
    s.film_thickness = w->film ? w->film_thickness_m : 0.0;
    s.paths = PATHS;
    s.seed = 7;
    return soak_measure_run(&s, r);
}

/* Largest |z| over the four angles of one preset state; -1 on a failure. */
static double compare_state(const soak_preset *p, const soak_liquid *water, double wetness)
{
    static const double deg[4] = {0, 30, 60, 80};
    soak_wet_params w;
    soak_wet_input in = soak_wet_input_steady(p, wetness);
    soak_scene scene;
    char err[512];
    if (soak_wetness_eval(p, water, &in, &w) != SOAK_OK ||
        soak_accuracy_preset_scene(p->name, "water", wetness, &scene, err, sizeof err) != SOAK_OK)
        return -1;
    double worst = 0;
    for (int a = 0; a < 4; ++a) {
        double c = cos(deg[a] * SOAK_PI / 180);
        soak_albedo_estimate e;
        soak_measure_result r;
        if (soak_material_albedo(&scene.materials[0], 1.0, c, SAMPLES, 11, 0, &e) != SOAK_OK ||
            measured(p, &w, c, &r) != SOAK_OK) {
            worst = -1;
            break;
        }
        double se = sqrt(e.std_error.g * e.std_error.g + r.std_error * r.std_error), z = (e.value.g - r.value) / se;
        printf("  %-10s w %.0f %2.0f deg: rendered %.5f +- %.5f, traced %.5f +- %.5f, z %+.2f\n", p->name, wetness,
               deg[a], e.value.g, e.std_error.g, r.value, r.std_error, z);
        worst = fmax(worst, fabs(z));
    }
    soak_scene_free(&scene);
    return worst;
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[512];
    if (!check_status("presets load", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    int n = 0;
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        if (p->kind == SOAK_KIND_CONDUCTOR || p->kind == SOAK_KIND_THIN_SHEET) continue;
        for (int wet = 0; wet <= 1; ++wet) {
            double z = compare_state(p, water, wet);
            char what[200];
            snprintf(what, sizeof what, "%s %s: rendered directional albedo = traced stack at 0/30/60/80 deg (max |z| %.2f <= 4)",
                     p->name, wet ? "wet" : "dry", z);
            check_true(what, z >= 0 && z <= 4.0);
            ++n;
        }
    }
    check_true("at least the seven opaque dielectric presets compared dry and wet", n >= 14);
    soak_presets_free(db);
    return check_finish();
}
