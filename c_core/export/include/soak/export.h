/* `soak export`: the versioned interface between the C core and the
 * renderer front ends (POV-Ray, Blender, OSL, and anyone writing another).
 *
 * Front ends never re-derive physics. Everything they need is computed here
 * from soak_wetness_eval (soak/wetness.h) and written by one target writer
 * per renderer; `soak export --target NAME` picks the writer from the table
 * in export.c.
 *
 * Two things are exported per preset and liquid:
 *
 * 1. Parameters over wetness at non-uniform knots (soak_export_knots): 0,
 *    the preset's saturation wetness (pores full, film starts: a kink in
 *    every curve) and 1, refined by bisection until linear interpolation
 *    between neighbouring knots stays within SOAK_EXPORT_KNOT_TOL of
 *    soak_wetness_eval on every exported quantity (colours, weights,
 *    roughness, phase; coefficients in 1/m within that tolerance relative;
 *    thin-sheet transmittance as 0.1 ln T: interpolate ln T).
 *
 * 2. The wetness function for ANY base colour (soak_wet_params_for_base,
 *    soak/base_colour.h): the preset's class (porosity, phase change,
 *    extinction, film, liquid) with its dry albedo replaced by the user's
 *    colour, channel by channel. Tabulated over (dry albedo, wetness) by soak_export_base_nodes, with
 *    bilinear interpolation within SOAK_EXPORT_BASE_TOL of the core.
 *
 * Steady state: the tables are at progress 1 (soak_wet_input_steady). The
 * pore-filling schedule (wetness.h step 1) only scales the delivered liquid:
 * L = w * clamp((t - t0) / t_fill, 0, 1), and every tabulated quantity depends
 * on (w, t) only through L, so a front end animating drying looks the tables
 * up at L instead of w. */
#ifndef SOAK_EXPORT_H
#define SOAK_EXPORT_H

#include <stddef.h>
#include <stdio.h>

#include "soak/base_colour.h"
#include "soak/preset.h"
#include "soak/status.h"
#include "soak/wetness.h"

#define SOAK_EXPORT_FORMAT "soak-export"
#define SOAK_EXPORT_FORMAT_VERSION 1
#define SOAK_EXPORT_GENERATOR "soak 1.0"

#define SOAK_EXPORT_KNOT_TOL 0.002 /* absolute, linear interpolation in wetness */
#define SOAK_EXPORT_BASE_TOL 0.005 /* absolute, bilinear in (dry albedo, wetness) */
#define SOAK_EXPORT_KNOTS_MAX 257

/* Wetness knots in [0,1], increasing, starting at 0 and ending at 1, with
 * the saturation wetness when it lies inside (0,1). film_thickness_m < 0:
 * the preset's default. *n receives the count (<= max). */
soak_status soak_export_knots(const soak_preset *preset, const soak_liquid *liquid, double film_thickness_m,
                              double *knots, int max, int *n);

/* Nodes of the base-colour table: dry albedos a_j (increasing, 0 .. 1)
 * and wetness knots w_i, so that bilinear interpolation of
 * soak_wet_params_for_base(...).albedo (and .albedo_total) over the grid
 * stays within SOAK_EXPORT_BASE_TOL, per channel. */
soak_status soak_export_base_nodes(const soak_preset *preset, const soak_liquid *liquid, double *albedo_nodes,
                                   int max_albedo, int *n_albedo, double *wet_knots, int max_wet, int *n_wet);

/* The view factor (soak_wetness_view_factor) on a fixed grid of view
 * angles, cos(view zenith) = i / (SOAK_EXPORT_VIEW_N - 1), for the state w of
 * (preset, liquid): out[i]. Front ends multiply their hemispherical colour by
 * it, interpolated linearly in cos, to follow the liquid interface's angular
 * transmission towards the viewer. */
#define SOAK_EXPORT_VIEW_N 17
soak_status soak_export_view_factors(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_params *w,
                                     soak_rgb out[SOAK_EXPORT_VIEW_N]);

/* Header facts every target writes: generator, format version, preset file
 * name (basename only: no absolute path) and its 64-bit FNV-1a hash. */
typedef struct soak_export_header {
    const char *generator;
    int format_version;
    char materials_file[256];
    char materials_hash[17]; /* 16 hex digits */
} soak_export_header;

soak_status soak_export_header_make(const soak_preset_db *db, soak_export_header *h);

/* What every target writer does first: checks its arguments and makes the
 * header, err naming the preset file when it cannot be read. */
soak_status soak_export_begin(const soak_preset_db *db, FILE *out, char *err, size_t errlen,
                              soak_export_header *h);

/* One target writer. It writes the whole export to out (a memory stream:
 * the command stages it and renames it into place). err names the cause on
 * failure. */
typedef soak_status (*soak_export_writer)(const soak_preset_db *db, FILE *out, char *err, size_t errlen);

typedef struct soak_export_target {
    const char *name;    /* --target value */
    const char *summary; /* one line for --help */
    const char *default_output; /* suggested file name (for docs) */
    soak_export_writer write;
} soak_export_target;

/* The table of targets (json, povray, blender, osl..., osl-math). */
const soak_export_target *soak_export_targets(int *count);
const soak_export_target *soak_export_find_target(const char *name);

/* Runs target on db and writes the result to path atomically (staged
 * temporary, then rename; a failure leaves any previous file untouched), or
 * to stdout when path is NULL or "-". */
soak_status soak_export_run(const soak_export_target *target, const soak_preset_db *db, const char *path, char *err,
                            size_t errlen);

/* The writers (one file each: export_json.c, export_povray.c, ...). */
/* The generic JSON interface (schema: c_core/data/export.schema.json). */
soak_status soak_export_write_json(const soak_preset_db *db, FILE *out, char *err, size_t errlen);
soak_status soak_export_write_povray(const soak_preset_db *db, FILE *out, char *err, size_t errlen);
soak_status soak_export_write_blender(const soak_preset_db *db, FILE *out, char *err, size_t errlen);
soak_status soak_export_write_osl(const soak_preset_db *db, FILE *out, char *err, size_t errlen);
soak_status soak_export_write_osl_legacy(const soak_preset_db *db, FILE *out, char *err, size_t errlen);
soak_status soak_export_write_osl_sheet(const soak_preset_db *db, FILE *out, char *err, size_t errlen);
soak_status soak_export_write_osl_wetmap(const soak_preset_db *db, FILE *out, char *err, size_t errlen);
/* The shaders' arithmetic (c_core/export/src/soak_wet_math.h, the same for
 * every preset file) with a generated-file banner. */
soak_status soak_export_write_osl_math(const soak_preset_db *db, FILE *out, char *err, size_t errlen);

#endif
