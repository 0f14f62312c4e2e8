/* Voxel grids of medium parameters (sigma_s, sigma_a, two-term HG phase,
 * wetness) and their file formats: what the bakers write (soak/bake_volume.h)
 * and the reference tracer reads (a scene's heterogeneous medium). Geometry
 * and the meaning of the channels: soak/bake_volume.h. */
#ifndef SOAK_VOLUME_H
#define SOAK_VOLUME_H

#include <stddef.h>

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

/* Medium parameters of a row at wetness w (linear between rows). */
soak_vol_medium soak_vol_rows_eval(const soak_vol_medium *rows, int n_rows, double w);

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
