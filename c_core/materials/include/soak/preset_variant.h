/* A named variant of a preset: the same material with its open porosity or
 * its film thickness changed, added to a loaded preset database so that
 * every consumer (`soak export`'s front-end tables, `soak eval`) sees it as a
 * preset of its own. [Hnat06] Fig. 5 sweeps the porosity alpha_poro of one
 * material; the gallery's front ends sweep it through such variants
 * (`soak export --variant clay_p20=clay,porosity=0.2`), and [Lag13]'s film
 * depths the same way (`--variant copper_f500=copper,film_mm=500`).
 *
 * The variant keeps everything of its base except:
 *  - porosity P in [1e-3, 0.95] (porous kinds): the open porosity alpha, and
 *    the two fields materials.json derives from it by its stated rules,
 *      ggx_alpha_wet = ggx_alpha_dry sqrt(1 - P)   (the pores' share becomes a
 *        flat liquid surface and mean-square slopes mix by area; the "rule"
 *        in every porous preset's roughness source),
 *      sigma_t       = sigma_t,base (1 - P) / (1 - P_base)   (the estimate
 *        3 (1 - porosity) / d of packed scatterers of size d, the same d);
 *    P = 0 makes a porous_dielectric a nonporous_dielectric: no pores, the
 *    dry roughness and phase function at every wetness, no fill time (the
 *    groups the loader reads for that kind). The chain (soak/wetness.h) then
 *    derives the saturation wetness, the pore water's share of the surface
 *    and the specular weights from P.
 *  - film thickness H in [0, 1000] mm (every kind): the film's depth where
 *    the liquid lies on top (wetness.h step 5).
 * A variant drops its base's "measured" group (the measurement was of the
 * base) and records what changed in its display name. */
#ifndef SOAK_PRESET_VARIANT_H
#define SOAK_PRESET_VARIANT_H

#include <stddef.h>

#include "soak/preset.h"
#include "soak/status.h"

#define SOAK_VARIANT_FILM_MAX_MM 1000.0 /* the loader's film_thickness_mm bound */

typedef struct soak_preset_change {
    int set_porosity, set_film; /* 1: the value below replaces the base's */
    double porosity;            /* [0, 0.95] */
    double film_thickness_mm;   /* [0, SOAK_VARIANT_FILM_MAX_MM] */
} soak_preset_change;

/* Adds preset `name` (a-z, 0-9, '_', '-', 1..31 characters, not yet in db),
 * base `base` with `change` applied, to db. On failure db is unchanged and
 * err names the cause: SOAK_ERR_NULL, SOAK_ERR_ARG (bad name, unknown base,
 * a value out of range, porosity on a kind without pores, nothing changed),
 * SOAK_ERR_NUMERIC (the medium cannot be derived), SOAK_ERR_NOMEM. The
 * database's preset array may move: pointers from soak_presets_at/_find
 * taken before the call are stale after it. */
soak_status soak_presets_add_variant(soak_preset_db *db, const char *name, const char *base,
                                     const soak_preset_change *change, char *err, size_t errlen);

/* Reads "NAME=BASE,key=value[,key=value]" (keys: porosity, film_mm) into
 * name (SOAK_PRESET_NAME_MAX bytes), base (SOAK_PRESET_NAME_MAX bytes) and
 * change; SOAK_ERR_ARG with the reason in err on a malformed text. Names and
 * ranges are checked by soak_presets_add_variant. */
soak_status soak_preset_variant_parse(const char *text, char *name, char *base, soak_preset_change *change,
                                      char *err, size_t errlen);

#endif
