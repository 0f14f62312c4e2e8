/* The mesh options of `soak bake rain` and `soak bake drops MESH` (UV set,
 * faces outside [0, 1]^2, --strict) and what a mesh bake says about its UVs
 * (bake_uv_cli.c; the rules in soak/bake_uv.h). */
#ifndef SOAK_BAKE_UV_CLI_H
#define SOAK_BAKE_UV_CLI_H

#include <stddef.h>

#include "cli.h"
#include "soak/bake_uv.h"
#include "soak/geometry.h"
#include "soak/image.h"

typedef struct bake_uv_opts {
    soak_mesh_uv_choice uv;
    int outside; /* soak_uv_outside */
    int strict;
} bake_uv_opts;

extern const cli_opt bake_uv_opts_table[];
extern const size_t bake_uv_opts_table_n;
#define BAKE_UV_TABLE(dst)                                                                                             \
    {                                                                                                                  \
        bake_uv_opts_table, bake_uv_opts_table_n, (dst)                                                                \
    }

void bake_uv_opts_init(bake_uv_opts *u);
/* After a bake: the warning on stderr when the stats call for one (then,
 * with --strict, an error and 1: write nothing); else 0. */
int bake_uv_verdict(const char *cmd, const char *mesh, const soak_uv_stats *s, const bake_uv_opts *u);
/* After a bake whose map covers texels: the warning when none of them
 * sees the sky (exposure 0 everywhere: the mesh faces away from --up, or
 * lies under its own faces); with --strict an error and 1; else 0. */
int bake_uv_dry_verdict(const char *cmd, const char *mesh, const soak_image *exposure, const soak_uv_stats *s,
                        const bake_uv_opts *u);
/* The report line on stdout: "uv: ..." */
void bake_uv_report(const char *label, const soak_uv_stats *s);
/* 1 when path names UDIM tiles (holds "<UDIM>"). */
int bake_uv_is_udim(const char *path);
/* path with "<UDIM>" replaced by tile; SOAK_ERR_ARG when it does not fit. */
soak_status bake_uv_tile_path(const char *path, int tile, char *out, size_t n);
/* soak bake rain with -o naming <UDIM> tiles (bake_rain_udim_cli.c):
 * paths are -o, --exposure, --water, --film (NULL: not asked for). */
struct bake_opts;
struct soak_rain_params;
int bake_rain_udim(const char *mesh_path, const struct soak_rain_params *p, const struct bake_opts *o,
                   const char *const *paths, const bake_uv_opts *u);
/* The same with --frames (bake_rain_udim_frames_cli.c): -o, --water and
 * --film hold <UDIM> and a frame number, --exposure <UDIM>. */
int bake_rain_udim_frames(const char *mesh_path, const struct soak_rain_params *p, const struct bake_opts *o,
                          const char *const *paths, const bake_uv_opts *u);
/* soak bake rain MESH --per-vertex OUT (bake_rain_vertex_cli.c): the
 * wetness per vertex through a generated atlas (soak/bake_vertex.h);
 * pov_name: the mesh2's identifier of an OUT.inc (NULL: the default). */
int bake_rain_vertex(const char *mesh_path, const struct soak_rain_params *p, const struct bake_opts *o,
                     const char *out, const char *pov_name, const bake_uv_opts *u);
/* 0, or the exit code after naming the output that lacks <UDIM>. */
int bake_rain_udim_check_paths(const char *const *paths);
/* Up to this many tiles in one run. */
#define BAKE_UDIM_MAX_TILES 100
/* The tiles mesh's faces use, or the exit code after saying why not. */
int bake_rain_udim_tiles(const char *mesh_path, const struct soak_mesh *mesh, int *tiles, int *n);
/* The mesh formats for --help. */
void bake_uv_formats_help(FILE *out);

#endif
