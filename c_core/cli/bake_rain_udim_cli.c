/* soak bake rain MESH -o wet.<UDIM>.exr: one bake per UDIM tile the mesh's
 * faces use (soak/bake_uv.h), every map of every tile written together or
 * none (soak/staged.h). Each tile's exposure sees the whole mesh; water does
 * not flow from one tile's map into another's. With --frames
 * (-o wet.<UDIM>.%04d.exr) one rain state per tile, and each frame's maps of
 * every tile written together. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_budget.h"
#include "bake_cli.h"
#include "bake_uv_cli.h"
#include "soak/bake_rain.h"
#include "soak/staged.h"

#define CMD "bake rain"
#define UDIM_MAX_TILES BAKE_UDIM_MAX_TILES

/* Bakes tile `tile` and stages its maps (the outputs given, in paths). */
static soak_status bake_tile(const soak_mesh *mesh, const bake_opts *o, soak_rain_params p, int tile,
                             const char *const *paths, soak_staged *stage, soak_uv_stats *total, char *err,
                             size_t errlen)
{
    soak_rain_result res;
    soak_bake_exec exec = {(int)o->threads, NULL, NULL};
    p.uv.udim_tile = tile;
    soak_status st = soak_bake_rain(mesh, (int)o->width, (int)o->height, &p, &exec, &res, err, errlen);
    if (st != SOAK_OK) return st;
    const soak_image *imgs[4] = {&res.wetness, &res.exposure, &res.water, &res.film};
    for (int k = 0; k < 4 && st == SOAK_OK; ++k) {
        char path[4096];
        if (!paths[k]) continue;
        st = bake_uv_tile_path(paths[k], tile, path, sizeof path);
        if (st != SOAK_OK) snprintf(err, errlen, "%s: the tile's file name is too long", paths[k]);
        else st = soak_bake_stage(stage, path, imgs[k], o->float_exr, err, errlen);
    }
    soak_uv_stats_add(total, &res.uv);
    soak_rain_result_free(&res);
    return st;
}

int bake_rain_udim_tiles(const char *mesh_path, const soak_mesh *mesh, int *tiles, int *n)
{
    char err[512] = "";
    if (soak_uv_udim_tiles(mesh, tiles, UDIM_MAX_TILES, n, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "%s: %s", mesh_path, err);
        return SOAK_EXIT_FAIL;
    }
    if (*n > UDIM_MAX_TILES) {
        cli_error(CMD, "%s: faces in %d UDIM tiles, more than the %d one run bakes", mesh_path, *n, UDIM_MAX_TILES);
        return SOAK_EXIT_USAGE;
    }
    return 0;
}

int bake_rain_udim_check_paths(const char *const *paths)
{
    for (int k = 1; k < 4; ++k)
        if (paths[k] && !bake_uv_is_udim(paths[k])) {
            cli_error(CMD, "-o names UDIM tiles: --exposure, --water and --film must hold <UDIM> too ('%s')", paths[k]);
            return SOAK_EXIT_USAGE;
        }
    return 0;
}

int bake_rain_udim(const char *mesh_path, const soak_rain_params *p, const bake_opts *o, const char *const *paths,
                   const bake_uv_opts *u)
{
    if (bake_rain_udim_check_paths(paths)) return SOAK_EXIT_USAGE;
    char err[4352] = "";
    soak_mesh mesh;
    soak_status st = soak_mesh_load_uv(mesh_path, &u->uv, &mesh, err, sizeof err);
    if (st != SOAK_OK) return bake_fail(CMD, st == SOAK_ERR_ARG ? SOAK_ERR_IO : st, err);
    int tiles[UDIM_MAX_TILES], n = 0, rc = bake_rain_udim_tiles(mesh_path, &mesh, tiles, &n);
    soak_staged stage;
    soak_staged_init(&stage);
    soak_uv_stats total;
    memset(&total, 0, sizeof total);
    for (int t = 0; t < n && !rc; ++t) {
        st = bake_tile(&mesh, o, *p, tiles[t], paths, &stage, &total, err, sizeof err);
        if (st != SOAK_OK) {
            cli_error(CMD, "%s: UDIM tile %d: %s", mesh_path, tiles[t], err[0] ? err : soak_status_str(st));
            rc = SOAK_EXIT_FAIL;
        }
    }
    if (n == 0) total.faces = (long long)mesh.n_triangles;
    soak_mesh_free(&mesh);
    if (!rc && bake_uv_verdict(CMD, mesh_path, &total, u)) rc = SOAK_EXIT_FAIL;
    if (rc) {
        soak_staged_abort(&stage);
        return rc;
    }
    st = soak_staged_commit(&stage, err, sizeof err);
    if (st != SOAK_OK) return bake_fail(CMD, st, err);
    printf("%s: %ldx%ld rain wetness in %d UDIM tile%s (%d..%d) from %s\n", o->output, o->width, o->height, n,
           n == 1 ? "" : "s", n ? tiles[0] : 0, n ? tiles[n - 1] : 0, mesh_path);
    bake_uv_report(o->output, &total);
    return SOAK_EXIT_OK;
}
