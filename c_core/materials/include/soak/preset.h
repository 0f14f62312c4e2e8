/* Material presets and liquids, loaded from a JSON data file
 * (c_core/data/materials.json; format described in its "description" field
 * and in docs through `soak materials --help`).
 *
 * Every field is validated on load: a missing or unknown key, a wrong type,
 * a duplicate key or name, a value out of range or non-finite is an error
 * whose message names the file, the JSON path (e.g. "materials[3].porosity.alpha")
 * and the reason. Which groups a preset must have depends on its kind:
 *
 *   group      porous_dielectric  thin_sheet  nonporous_dielectric  conductor
 *   albedo            x               x               x                 x
 *   roughness    dry + wet       dry + wet          dry               dry
 *   ior            n (scalar)     n (scalar)      n (scalar)     n[3], k[3]
 *   porosity          x               x               -                 -
 *   medium            x               x               x                 -
 *   phase        dry + wet       dry + wet          dry                -
 *   wetting     t_fill + film   t_fill + film      film              film
 *   sheet             -               x               -                 -
 *   measured      optional        optional        optional          optional
 *
 * Keys: top level {format: "soak-materials", version: 1, description,
 * materials: [...], liquids: [...]}; a material {name, display_name, kind,
 * albedo {rgb, source}, roughness {ggx_alpha_dry, ggx_alpha_wet, source},
 * ior {n, k, source}, porosity {alpha, s_p, source}, medium {sigma_t_per_mm,
 * source}, phase {dry {g1, g2, w}, wet {g1, g2, w}, source}, wetting {t_fill,
 * film_thickness_mm, source, contact_angle_deg, contact_angle_source}, sheet {thickness_mm, or grammage_g_m2 and
 * density_kg_m3 (thickness = grammage / density), source}, measured
 * {wet_dry_ratio, spread, dry_albedo, wetness, quantity, source}}; a liquid {name,
 * display_name, ior, sigma_a_per_mm, sigma_s_per_mm, source}.
 *
 * Units: the file gives extinction sigma_t and liquid sigma_a/sigma_s in
 * 1/mm and thicknesses in mm (its keys say so); the loader converts them
 * once (soak/units.h) and every field below is in SI, m and 1/m. Albedo is
 * linear RGB: the diffuse albedo for dielectrics, the normal-incidence
 * reflectance F0 for conductors (checked against n, k).
 *
 * Derived on load: the single-scattering albedo omega of the dry medium by
 * inverting the dry albedo with van de Hulst's formula (soak/vdhulst.h) at
 * the dry mean cosine, and sigma_s = omega sigma_t, sigma_a = (1-omega)
 * sigma_t. Storing sigma_t rather than sigma_s and sigma_a keeps the medium
 * and the albedo consistent by construction.
 *
 * No global state: a soak_preset_db owns everything it returns. */
#ifndef SOAK_PRESET_H
#define SOAK_PRESET_H

#include <stddef.h>

#include "soak/hg.h"
#include "soak/status.h"
#include "soak/vec.h"

typedef enum soak_material_kind {
    SOAK_KIND_POROUS_DIELECTRIC = 0, /* liquid enters pores: phase change + film */
    SOAK_KIND_NONPOROUS_DIELECTRIC,  /* polished stone, glaze: film only */
    SOAK_KIND_CONDUCTOR,             /* metals: film over a specular base */
    SOAK_KIND_THIN_SHEET             /* porous and thin (paper, cloth): like porous + thickness */
} soak_material_kind;

/* "porous_dielectric", "nonporous_dielectric", "conductor", "thin_sheet". */
const char *soak_material_kind_name(soak_material_kind kind);
/* 1 for the kinds liquid can enter (porous_dielectric, thin_sheet). */
int soak_material_kind_porous(soak_material_kind kind);

#define SOAK_PRESET_NAME_MAX 32   /* name: [a-z0-9_-], 1..31 chars */
#define SOAK_PRESET_TEXT_MAX 2048 /* display names and source strings */

typedef struct soak_preset {
    const char *name;
    const char *display_name;
    soak_material_kind kind;

    soak_rgb albedo; /* dry, linear RGB, [0,1] */
    const char *albedo_source;

    double ggx_alpha_dry; /* GGX width, [1e-4, 1] */
    double ggx_alpha_wet; /* with pores full, <= dry; equals dry for non-porous kinds */
    const char *roughness_source;

    double ior;        /* dielectrics: real index relative to air, [1, 3]; 0 for conductors */
    soak_rgb ior_n;    /* conductors: complex index n + i k per channel; zero otherwise */
    soak_rgb ior_k;
    const char *ior_source;

    double porosity;   /* open porosity alpha, (0, 0.95] for porous kinds, 0 otherwise */
    double s_p;        /* Merillou pore depth/diameter ratio, 0 for non-porous kinds */
    const char *porosity_source;

    soak_rgb sigma_t_per_m; /* extinction, 1/m; zero for conductors */
    const char *medium_source;

    soak_hg2 phase_dry; /* w is the weight of the g1 lobe (soak/hg.h) */
    soak_hg2 phase_wet; /* equals phase_dry for non-porous kinds */
    const char *phase_source;

    double t_fill;            /* default pore fill time ([Hnat06] relative units), >= 0 */
    double film_thickness_m;  /* default film thickness, m, >= 0 */
    const char *wetting_source;
    /* Water's static contact angle on the dry solid, deg, [0, 180]: beading
     * above `soak bake beads --bead-above` (soak/bake_beads.h). Optional key
     * wetting.contact_angle_deg (with its own contact_angle_source): -1 and
     * NULL when absent. */
    double contact_angle_deg;
    const char *contact_angle_source;

    double thickness_m;  /* thin sheets: sheet thickness, m; 0 = semi-infinite */
    const char *sheet_source;

    /* Optional "measured" group: a published wet/dry reflectance ratio the
     * wet parameters are calibrated against (docs/calibration.md). The
     * ratio is quantity(wetness) / dry_albedo for the chain evaluated at the
     * grey dry albedo of the measured sample; spread is the measurement's
     * half range. has_measured = 0 when the group is absent. */
    int has_measured;
    double measured_ratio;      /* [0, 10] */
    double measured_spread;     /* [0, 1] */
    double measured_dry_albedo; /* (0, 1] */
    double measured_wetness;    /* [0, 1] */
    int measured_total;         /* 1: albedo_total (film specular included), 0: albedo */
    double measured_sun_zenith_deg; /* the measurement's light: a sun at this zenith
                                     * angle, [0, 90] (required key); a hand-built
                                     * preset may set < 0 for uniform diffuse light */
    const char *measured_source;

    /* Derived on load (see above). Zero for conductors. */
    soak_rgb omega_dry;   /* single-scattering albedo of the dry medium */
    soak_rgb sigma_s_dry_per_m;
    soak_rgb sigma_a_dry_per_m;
} soak_preset;

#define SOAK_SIGMA_T_MAX_PER_M 1e8       /* a preset's extinction (1e5 / mm) */
#define SOAK_LIQUID_SIGMA_MAX_PER_M 1e6  /* a liquid's coefficients (1000 / mm) */

typedef struct soak_liquid {
    const char *name;
    const char *display_name;
    double ior;       /* relative to air, [1, 3] */
    soak_rgb sigma_a_per_m; /* absorption, [0, SOAK_LIQUID_SIGMA_MAX_PER_M] */
    soak_rgb sigma_s_per_m; /* scattering, [0, SOAK_LIQUID_SIGMA_MAX_PER_M] */
    const char *source;
} soak_liquid;

typedef struct soak_preset_db soak_preset_db;

/* Loads and validates path (NULL: soak_presets_default_path()). On failure
 * *db is untouched and err (if non-NULL) holds "<file>: <json path>: <reason>".
 * SOAK_ERR_IO: unreadable; SOAK_ERR_PARSE: syntax, missing/unknown/duplicate
 * key, wrong type; SOAK_ERR_ARG: value out of range or non-finite;
 * SOAK_ERR_NOMEM. */
soak_status soak_presets_load(const char *path, soak_preset_db **db, char *err, size_t errlen);
void soak_presets_free(soak_preset_db *db);

/* The presets file read when none is named: the environment variable
 * SOAK_MATERIALS if set and non-empty, else materials.json of the data
 * folder (search order: soak/data_dir.h). Writes it to out (n bytes;
 * SOAK_PRESETS_PATH_MAX is enough); on failure out is untouched and err
 * names the folders tried (SOAK_ERR_NOT_FOUND) or the overlong path
 * (SOAK_ERR_ARG). */
#define SOAK_PRESETS_PATH_MAX 4096
soak_status soak_presets_default_path(char *out, size_t n, char *err, size_t errlen);

/* The path the database was loaded from. */
const char *soak_presets_path(const soak_preset_db *db);

int soak_presets_count(const soak_preset_db *db);
const soak_preset *soak_presets_at(const soak_preset_db *db, int index); /* NULL if out of range */
const soak_preset *soak_presets_find(const soak_preset_db *db, const char *name); /* NULL if absent */

/* Recomputes the derived fields (omega_dry, sigma_s_dry_per_m,
 * sigma_a_dry_per_m) of a preset built or edited by hand from albedo,
 * phase_dry and sigma_t_per_m; the loader calls it. Conductors: the derived
 * fields are set to zero. */
soak_status soak_preset_derive(soak_preset *preset);

int soak_presets_liquid_count(const soak_preset_db *db);
const soak_liquid *soak_presets_liquid_at(const soak_preset_db *db, int index);
const soak_liquid *soak_presets_find_liquid(const soak_preset_db *db, const char *name);

#endif
