/* 3D parameter volumes for subsurface scattering of wet materials.
 *
 * Seed 000 (Jensen, Legakis, Dorsey 1999, sections 3.2 and 4) renders wet
 * materials as participating media whose scattering coefficient sigma_s,
 * absorption coefficient sigma_a and two-term Henyey-Greenstein phase
 * parameters (g1, g2, w; seed 000 Eq. 5, see soak/hg.h) are modulated by a
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
 * Penetration profile (our model; the seeds give none): water drawn in by
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

/* Homogeneous medium parameters of one state (dry or wet). */
typedef struct soak_vol_medium {
    soak_rgb sigma_s; /* scattering coefficient per length unit, >= 0 */
    soak_rgb sigma_a; /* absorption coefficient per length unit, >= 0 */
    double g1;        /* HG lobe 1 asymmetry, |g1| <= SOAK_HG_G_MAX */
    double g2;        /* HG lobe 2 asymmetry, |g2| <= SOAK_HG_G_MAX */
    double w;         /* weight of lobe 1, [0,1] */
} soak_vol_medium;

#define SOAK_VOL_SIGMA_MAX 1e9

soak_status soak_vol_medium_validate(const soak_vol_medium *m);

typedef enum soak_vol_channel {
    SOAK_VOL_SIGMA_S_R = 0,
    SOAK_VOL_SIGMA_S_G,
    SOAK_VOL_SIGMA_S_B,
    SOAK_VOL_SIGMA_A_R,
    SOAK_VOL_SIGMA_A_G,
    SOAK_VOL_SIGMA_A_B,
    SOAK_VOL_G1,
    SOAK_VOL_G2,
    SOAK_VOL_W,
    SOAK_VOL_WETNESS,
    SOAK_VOL_NCHANNELS
} soak_vol_channel;

/* "sigma_s_r", ..., "g1", "g2", "w", "wetness"; NULL out of range. */
const char *soak_volume_channel_name(int channel);

#define SOAK_VOLUME_MAX_DIM 4096

typedef struct soak_volume {
    int nx, ny, nz;
    double size[3]; /* box extent sx, sy, sz > 0 */
    float *data;    /* SOAK_VOL_NCHANNELS planes of nx*ny*nz floats, x fastest, then y, then z */
} soak_volume;

/* Zeroed volume; dims in [1, SOAK_VOLUME_MAX_DIM], size finite > 0. */
soak_status soak_volume_alloc(soak_volume *v, int nx, int ny, int nz, const double size[3]);
void soak_volume_free(soak_volume *v);
static inline size_t soak_volume_count(const soak_volume *v)
{
    return (size_t)v->nx * (size_t)v->ny * (size_t)v->nz;
}
static inline float *soak_volume_plane(const soak_volume *v, int channel)
{
    return v->data + (size_t)channel * soak_volume_count(v);
}
static inline size_t soak_volume_index(const soak_volume *v, int i, int j, int k)
{
    return ((size_t)k * (size_t)v->ny + (size_t)j) * (size_t)v->nx + (size_t)i;
}

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

/* 3D noise wetness (seed 000 sec. 4.2: wetness "modelled using a sum of
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

/* Medium parameters of a row at wetness w (linear between rows). */
soak_vol_medium soak_vol_rows_eval(const soak_vol_medium *rows, int n_rows, double w);

/* Wetness table of a preset soaked with a liquid (soak_wetness_table, steady
 * state, the preset's film thickness): sigma_s, sigma_a converted from 1/mm
 * to 1/(length unit) with unit_mm = millimetres per length unit of the box
 * (1000 for metres), phase g1, g2, w. A conductor has no medium:
 * SOAK_ERR_ARG. */
soak_status soak_vol_rows_from_preset(const soak_preset *preset, const soak_liquid *liquid, double unit_mm,
                                      int n_rows, soak_vol_medium *rows);

/* ---- Writers (all atomic: temp files renamed only when every file of the
 * set is complete; on failure nothing is left) ---- */

/* POV-Ray df3, one file per channel: <prefix>_<channel>.df3, plus
 * <prefix>_df3.json (per-channel "offset" and "scale": real = offset + scale *
 * stored, stored = raw / (2^bits - 1)) and <prefix>.inc (the same numbers as
 * #declares and a density macro). bits is 8, 16 or 32.
 * Layout for POV-Ray's interpolate 1 (voxel j sits at j/M and wraps modulo
 * M): each axis has M = N + 2 voxels, our N voxels in the middle and one
 * replicated voxel on each side, and the density pattern is transformed with
 *     scale M/N  translate -0.5/N      (per axis, unit-box coordinates)
 * so that our voxel centres land at (i + 0.5)/N and trilinear interpolation
 * never wraps (clamp-to-edge at the faces). For interpolate 0 the matching
 * transform is scale M/N translate -1/N. The unit container box { 0, 1 }
 * scaled by <sx, sy, sz> is the volume box; POV-Ray media coefficients are
 * per world unit (checked: scaling a container by 2 squares its
 * transmittance), so the sigma values hold when the world unit is the
 * volume's length unit. */
soak_status soak_volume_write_df3(const soak_volume *v, const char *prefix, int bits, char *err, size_t errlen);

/* Soak grid format, read by the reference tracer (soak_volume_read_grid):
 * <prefix>.json header and <prefix>.raw data.
 *   { "format": "soak-volume-grid", "version": 1,
 *     "dims": [nx, ny, nz], "size": [sx, sy, sz],
 *     "cell_centered": true, "order": "x fastest, then y, then z",
 *     "dtype": "float32le", "data": "<basename of .raw>",
 *     "channels": ["sigma_s_r", ..., "wetness"],   -- planes in this order
 *     "units": "sigma per length unit of size",
 *     "model": { "wetness_table": [{...}, ...], "penetration_depth": d } }
 * ("model" is informative; rows may be NULL, then it is left out).
 * The .raw file holds the planes back to back, each nx*ny*nz little-endian
 * IEEE float32, no header; its size must be exactly
 * channels * nx*ny*nz * 4 bytes. Voxel (i,j,k) centre =
 * ((i+0.5) sx/nx, (j+0.5) sy/ny, (k+0.5) sz/nz); values are cell averages,
 * sample with trilinear interpolation clamped to the edge voxels. */
soak_status soak_volume_write_grid(const soak_volume *v, const char *prefix, const soak_vol_medium *rows, int n_rows,
                                   double penetration_depth, char *err, size_t errlen);
/* Reads a grid written above (any channel order containing all channels). */
soak_status soak_volume_read_grid(const char *json_path, soak_volume *v, char *err, size_t errlen);

/* OpenVDB file with float grids sigma_s, sigma_a (mean of the RGB channels),
 * sigma_s_r/g/b, sigma_a_r/g/b, g1, g2, w, wetness and "density" (mean
 * extinction sigma_s + sigma_a, a fog volume, for Blender's volume object).
 * Transform: voxel size (sx/nx, sy/ny, sz/nz), index (i,j,k) at the cell
 * centre, so the voxels exactly cover the box. SOAK_ERR_UNSUPPORTED when
 * libsoak was built without OpenVDB. */
soak_status soak_volume_write_vdb(const soak_volume *v, const char *path, char *err, size_t errlen);
/* The three writers above as members of one set of outputs replaced
 * together (soak/staged.h): nothing reaches the prefix's files before
 * soak_staged_commit. */
struct soak_staged;
soak_status soak_volume_stage_df3(struct soak_staged *stage, const soak_volume *v, const char *prefix, int bits,
                                  char *err, size_t errlen);
soak_status soak_volume_stage_grid(struct soak_staged *stage, const soak_volume *v, const char *prefix,
                                   const soak_vol_medium *rows, int n_rows, double penetration_depth, char *err,
                                   size_t errlen);
soak_status soak_volume_stage_vdb(struct soak_staged *stage, const soak_volume *v, const char *path, char *err,
                                  size_t errlen);
/* 1 when the build has OpenVDB. */
int soak_volume_have_vdb(void);
/* Reads one float grid through OpenVDB: the value at each index (i,j,k) of
 * [0,nx)x[0,ny)x[0,nz) into values (x fastest), and the world-space voxel
 * size and the world position of voxel (0,0,0). */
soak_status soak_volume_read_vdb_grid(const char *path, const char *grid, int nx, int ny, int nz, float *values,
                                      double voxel_size[3], double origin[3], char *err, size_t errlen);

#endif
