/* How a mesh's faces reach a baked map in UV space (the rain bake's step 1,
 * soak/bake_rain.h; `soak bake rain` and `soak bake drops MESH`), and what
 * the bake says about it.
 *
 * Texel (x, y) of a W x H map is covered by a face when its centre
 * (x + 1/2, y + 1/2) lies in the face's UV triangle scaled to (u W,
 * (1 - v) H). Faces are handled as follows:
 *  - without UVs (a part of the file without the chosen UV set,
 *    soak_mesh.tri_uv): skipped and counted;
 *  - degenerate (UV area or surface area 0, e.g. every corner at one UV):
 *    skipped and counted;
 *  - outside [0, 1]^2 (beyond a tolerance of 1e-6), without UDIM: wrapped
 *    (moved by whole tiles so that its lowest corner lies in [0, 1)^2, and
 *    what still extends past 1 wraps around the map, as a repeating
 *    texture), skipped, or the bake refused (soak_uv_outside);
 *  - UDIM (tile 1001 + k + 10 l covers u in [k, k+1), v in [l, l+1); the
 *    tile of a face is the one holding its UV centroid): a tile's bake takes
 *    the faces of that tile, moved by (-k, -l); the parts of a face past its
 *    tile's border are cut off there (counted as outside);
 *  - overlapping faces (several over one texel centre): the texel takes the
 *    face with the most surface per texel (largest world area per texel
 *    area), ties broken by the surface point's coordinates, then its normal
 *    and UV derivatives: a total order on what the texel stores, so the map
 *    does not depend on the order of the faces in the file. The share of
 *    covered texels under more than one face is reported.
 * Faces that cover no texel centre at all (smaller than a texel) are
 * counted, with the UV area they hold. */
#ifndef SOAK_BAKE_UV_H
#define SOAK_BAKE_UV_H

#include <stddef.h>

#include "soak/geometry.h"
#include "soak/status.h"

typedef enum soak_uv_outside {
    SOAK_UV_WRAP = 0, /* default: wrapped as a repeating texture */
    SOAK_UV_SKIP,     /* left out, counted */
    SOAK_UV_REFUSE    /* the bake fails naming the first such face */
} soak_uv_outside;

typedef struct soak_uv_options {
    soak_uv_outside outside;
    int udim_tile; /* 0: no UDIM; else the tile baked, 1001..1999 */
} soak_uv_options;

#define SOAK_UV_TOL 1e-6
#define SOAK_UDIM_FIRST 1001
#define SOAK_UDIM_LAST 1999
/* A bake warns (and with --strict fails) when faces holding more than
 * this share of the mesh's UV area cover no texel centre. */
#define SOAK_UV_MIN_SEEN 0.5

typedef struct soak_uv_stats {
    long long texels, covered, shared; /* of the map: covered by a face; by more than one */
    long long faces, baked_faces;      /* all faces; faces that cover a texel */
    long long no_uv_faces, degenerate_faces, outside_faces, other_tile_faces, unseen_faces;
    int outside_wrapped;          /* 1: the outside faces were wrapped, 0: skipped (or cut at a tile) */
    double uv_area, uv_area_seen; /* UV area (tile units) of the faces baked, of those covering a texel */
} soak_uv_stats;

/* 1 and a message (stderr's warning, without "warning: ") when the stats
 * describe a map that says less than the mesh: no texel covered, faces
 * without UVs, or faces holding over SOAK_UV_MIN_SEEN of the UV area
 * falling between texel centres; else 0. */
int soak_uv_stats_warning(const soak_uv_stats *s, char *msg, size_t n);
/* The bake's report line: covered and shared texels, skipped faces by
 * reason. */
void soak_uv_stats_line(const soak_uv_stats *s, char *buf, size_t n);
/* Adds b's counts to a (the tiles of a UDIM bake). */
void soak_uv_stats_add(soak_uv_stats *a, const soak_uv_stats *b);

/* The UDIM tiles the faces with UVs use, ascending, at most max (*count
 * may exceed max: then only the first max are stored). SOAK_ERR_ARG with
 * err naming a face whose UV centroid is outside u in [0, 10), v in
 * [0, 100). */
soak_status soak_uv_udim_tiles(const soak_mesh *m, int *tiles, int max, int *count, char *err, size_t errlen);

#endif
