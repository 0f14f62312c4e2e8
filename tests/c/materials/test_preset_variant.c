/* soak_presets_add_variant (soak/preset_variant.h): a failed call leaves the
 * presets as they were; a variant owns its name (the caller's buffer may go);
 * porosity 0 makes a material without pores (the loader's nonporous kind:
 * wet = dry at every wetness below a film); the chain reads the new porosity
 * (saturation = P, the water's mirror weight P with the pores full, the
 * material's own weight 1 - P: [Hnat06] Eq. 3 at G_p = 1); the wet roughness
 * follows the file's rule alpha_dry sqrt(1 - P). The values against a preset
 * file written by hand: tests/cli/export.sh. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "soak/preset.h"
#include "soak/preset_variant.h"
#include "soak/wetness.h"

static void failures(soak_preset_db *db)
{
    char err[512];
    const int n = soak_presets_count(db);
    soak_preset_change bad = {.set_porosity = 1, .porosity = 0.96};
    check_status("porosity 0.96 refused", soak_presets_add_variant(db, "v", "clay", &bad, err, sizeof err),
                 SOAK_ERR_ARG);
    check_true("the message names the porosity", strstr(err, "porosity 0.96") != NULL);
    bad.porosity = NAN;
    check_status("porosity NaN refused", soak_presets_add_variant(db, "v", "clay", &bad, err, sizeof err),
                 SOAK_ERR_ARG);
    check_status("porosity on copper refused", soak_presets_add_variant(db, "v", "copper", &bad, err, sizeof err),
                 SOAK_ERR_ARG);
    soak_preset_change film = {.set_film = 1, .film_thickness_mm = 1001};
    check_status("film 1001 mm refused", soak_presets_add_variant(db, "v", "clay", &film, err, sizeof err),
                 SOAK_ERR_ARG);
    soak_preset_change none = {0};
    check_status("no change refused", soak_presets_add_variant(db, "v", "clay", &none, err, sizeof err), SOAK_ERR_ARG);
    film.film_thickness_mm = 1;
    check_status("a taken name refused", soak_presets_add_variant(db, "sand", "clay", &film, err, sizeof err),
                 SOAK_ERR_ARG);
    check_status("a bad name refused", soak_presets_add_variant(db, "Clay 2", "clay", &film, err, sizeof err),
                 SOAK_ERR_ARG);
    check_status("NULL db", soak_presets_add_variant(NULL, "v", "clay", &film, err, sizeof err), SOAK_ERR_NULL);
    check_close("the presets unchanged after the failures", soak_presets_count(db), n, 0);
}

static void pores(soak_preset_db *db, const soak_liquid *water)
{
    char name[8] = "v_p30", err[512];
    soak_preset_change c = {.set_porosity = 1, .porosity = 0.3};
    check_status("clay at porosity 0.3", soak_presets_add_variant(db, name, "clay", &c, err, sizeof err), SOAK_OK);
    strcpy(name, "xxxxx");
    const soak_preset *v = soak_presets_find(db, "v_p30"), *clay = soak_presets_find(db, "clay");
    if (!check_true("the variant keeps its own name", v != NULL)) return;
    check_close("wet roughness alpha_dry sqrt(1 - P)", v->ggx_alpha_wet, clay->ggx_alpha_dry * sqrt(0.7), 1e-12);
    soak_wet_input in = soak_wet_input_steady(v, 0.3);
    soak_wet_params w;
    if (!check_status("chain at the saturation", soak_wetness_eval(v, water, &in, &w), SOAK_OK)) return;
    check_close("saturation = P", w.saturation, 0.3, 1e-12);
    check_close("pores full: water's mirror weight = P", w.water_specular_weight, 0.3, 1e-12);
    check_close("material's own weight = 1 - P", w.specular_weight, 0.7, 1e-12);
    c.porosity = 0.0;
    check_status("clay at porosity 0", soak_presets_add_variant(db, "v_p00", "clay", &c, err, sizeof err), SOAK_OK);
    v = soak_presets_find(db, "v_p00");
    check_true("porosity 0: nonporous_dielectric", v && v->kind == SOAK_KIND_NONPOROUS_DIELECTRIC);
    in = soak_wet_input_steady(v, 0.5);
    if (v && check_status("chain at wetness 0.5", soak_wetness_eval(v, water, &in, &w), SOAK_OK)) {
        check_close("no pores: none filled", w.fill, 0.0, 0.0);
        check_close("no pores: the liquid is all film (coverage = wetness)", w.film_coverage, 0.5, 1e-12);
    }
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[256];
    if (!check_status("presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    failures(db);
    pores(db, soak_presets_find_liquid(db, "water"));
    soak_presets_free(db);
    return check_finish();
}
