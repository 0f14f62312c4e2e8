/* The flat tables the OSL shaders carry (export_osl.c), shared with the C
 * test that evaluates them through soak_wet_math.h against the core.
 * Index k = kept preset * n_liquids + liquid. */
#ifndef SOAK_EXPORT_OSL_TABLES_H
#define SOAK_EXPORT_OSL_TABLES_H

#include "soak/export.h"

typedef struct soak_float_list {
    float *v;
    int n, cap;
} soak_float_list;

typedef struct soak_int_list {
    int *v;
    int n, cap;
} soak_int_list;

typedef struct soak_osl_tables {
    int n_presets, n_liquids; /* presets kept (all, or the thin sheets) */
    soak_int_list preset;    /* per kept preset: its index in the preset file */
    soak_int_list kind;      /* per preset: 0 dielectric, 1 conductor, 2 thin sheet */
    /* knot tables: wetness, albedo (rgb, stride 3), interface coverage
     * (film + pore water), roughness sqrt(alpha), ln of the sheet transmittance (rgb, floored at 1e-6),
     * view factor (SOAK_EXPORT_VIEW_N rgb per knot, at 3 SOAK_EXPORT_VIEW_N k_off), the
     * material's own rough lobe's weight (wetness.h step 6's specular weight; 0 for
     * conductors and sheets), the film's coverage c alone (the lobe stays in air over
     * 1 - c: soak/wet_specular.h point 1) */
    soak_float_list kw, ka, kc, kr, kt, kv, ks, kf;
    soak_float_list ior;     /* per preset: the material's index (its lobe's Fresnel) */
    soak_int_list k_off, k_n;
    /* base-colour tables: nodes and values [channel][wetness][albedo] */
    soak_float_list ba, bw, bg;
    soak_int_list ba_off, ba_n, bw_off, bw_n, bg_off; /* bg_off: per k and channel (3 k + c) */
} soak_osl_tables;

/* sheets_only: keep the thin-sheet presets only (soak_wet_sheet.osl). */
soak_status soak_osl_tables_build(const soak_preset_db *db, int sheets_only, soak_osl_tables *t);
void soak_osl_tables_free(soak_osl_tables *t);

#endif
