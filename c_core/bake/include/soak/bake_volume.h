/* 3D parameter volumes for subsurface scattering of wet materials.
 *
 * [JLD99] (Jensen, Legakis, Dorsey 1999, sections 3.2 and 4) renders wet
 * materials as participating media whose scattering coefficient sigma_s,
 * absorption coefficient sigma_a and two-term Henyey-Greenstein phase
 * parameters (g1, g2, w; [JLD99] Eq. 5, see soak/hg.h) are modulated by a
 * wetness function: dry values where the material is dry, wet values where
 * it is wet. This module bakes that modulation into voxel grids.
 *
 * Geometry: the volume is the box [0,sx] x [0,sy] x [0,sz] (any length unit;
 * sigma values are per that unit), z up. Voxels are cell-centred: voxel
 * (i,j,k) covers [i,i+1]*sx/nx x ... and its value is the average over the
 * cell. The top face z = sz is the wetted surface.
 *
 * Wetness (0 dry .. 1 saturated) comes from one of:
 *  - a surface wetness map mapped onto the top face (image column 0 at x = 0,
 *    top image row at y = sy, as POV-Ray maps images), carried down to a
 *    penetration depth delta by the profile p below;
 *  - a uniform surface wetness with the same profile;
 *  - a 3D wetness function evaluated at voxel centres (used as is).
 *
 * Penetration profile (our model; the sources give none): water drawn in by
 * capillarity fills the pores behind a wetting front (Lucas-Washburn), so
 * the material is saturated near the surface and dry beyond the front. We
 * smooth the front with the C1 cubic:
 *     p(d) = 1 - S(d/delta),  S(t) = 3t^2 - 2t^3 for t in [0,1], S = 1 beyond,
 * d = depth below the top face. p(0) = 1, p'(0) = 0 (saturated skin),
 * p(delta) = 0, p'(delta) = 0 (no kink at the front), and the water column
 * integral_0^inf p = delta/2. delta = 0 means no penetration: every voxel is
 * dry (the cell averages below make this the exact limit).
 * A voxel stores surface_wetness * (cell average of p over its depth range),
 * so the column water content is the same at any resolution.
 *
 * Parameters per voxel come from a wetness table: rows of medium parameters
 * at wetness w_i = i/(n-1), interpolated linearly in w between rows (the
 * contract of soak/wetness.h for front ends). A material preset gives the
 * table through soak_wetness_table (soak_vol_rows_from_preset); raw dry and
 * wet parameters are the two-row table, i.e. X = (1-w) X_dry + w X_wet for
 * sigma_s, sigma_a (per RGB channel), g1, g2 and w: the modulation of seed
 * 000 sections 4.1-4.3 (paper g1 0.05 -> 0.8, g2 -0.05 -> -0.1, w 0.2 -> 0.1;
 * rock forward scattering 0.1 -> 0.8). For the coefficients this is also the
 * volume-fraction mixing rule (coefficients add by number density). */
#ifndef SOAK_BAKE_VOLUME_H
#define SOAK_BAKE_VOLUME_H

#include <stddef.h>

#include "soak/bake.h"
#include "soak/image.h"
#include "soak/preset.h"
#include "soak/status.h"
#include "soak/vec.h"
#include "soak/volume.h"


/* Profile p(d) above; depth >= 0, delta >= 0. */
double soak_wet_profile(double depth, double delta);
/* Mean of p over depths [d0, d1] (0 <= d0 <= d1); p(d0) when d0 == d1. */
double soak_wet_profile_mean(double d0, double d1, double delta);

/* Wetness in [0,1] at a point of the box (values outside are clamped). */
typedef double (*soak_wetness3d_fn)(void *ctx, double x, double y, double z);

typedef struct soak_volume_source {
    const soak_image *surface_map; /* mean of its colour channels; NULL: uniform */
    double surface_wetness;        /* [0,1], used when surface_map is NULL */
    double penetration_depth;      /* delta >= 0, box length unit */
    soak_wetness3d_fn wetness3d;   /* if set, replaces map + profile */
    void *wetness3d_ctx;
} soak_volume_source;

#define SOAK_VOL_ROWS_MAX 4097

/* Fills every channel of v (already allocated) from the source and the
 * wetness table rows[0..n_rows-1] (2 <= n_rows <= SOAK_VOL_ROWS_MAX, every
 * row valid). Map values are clamped to [0,1]; NaN in the map or from
 * wetness3d is SOAK_ERR_ARG. */
soak_status soak_volume_bake(soak_volume *v, const soak_vol_medium *rows, int n_rows, const soak_volume_source *src,
                             const soak_bake_exec *exec);
/* exec: threads and progress (soak/bake.h; NULL = every core, no progress).
 * Every voxel is computed independently, so the result does not depend on
 * the thread count; wetness3d must then be thread-safe. */

/* 3D noise wetness ([JLD99] sec. 4.2: wetness "modelled using a sum of
 * turbulence functions"): the octave sum of soak_noise3 (soak/bake.h;
 * octave o uses seed soak_seed_derive(seed, o) at frequency
 * frequency * lacunarity^o cells per `length`), normalised by sum gain^o.
 * fBm (values about [-1,1]) maps to wetness 0.5 + 0.5 v; turbulence (|noise|
 * summed, [0,1]) is used as is; thresholded: smoothstep(threshold -
 * softness, threshold + softness, v). Clamped to [0,1]. The 2D-only fields
 * of params (tileable, use_3d, z) are ignored. */
typedef struct soak_vol_turbulence {
    soak_turbulence_params params;
    double length; /* box length that holds `frequency` noise cells, > 0 */
} soak_vol_turbulence;
soak_status soak_vol_turbulence_check(const soak_vol_turbulence *t);
/* A soak_wetness3d_fn; ctx is a checked const soak_vol_turbulence *. */
double soak_vol_turbulence_wetness(void *ctx, double x, double y, double z);


/* Wetness table of a preset soaked with a liquid (soak_wetness_table, steady
 * state, the preset's film thickness): sigma_s, sigma_a converted from the
 * chain's 1/m to 1/(length unit) with m_per_unit = metres per length unit
 * of the box, in [1e-12, 1e6] (1 for metres, 1e-3 for mm), phase g1, g2, w.
 * A conductor has no medium: SOAK_ERR_ARG. */
soak_status soak_vol_rows_from_preset(const soak_preset *preset, const soak_liquid *liquid, double m_per_unit,
                                      int n_rows, soak_vol_medium *rows);

#endif
