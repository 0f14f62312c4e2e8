/* soak bake rain MESH --frames A-B -o wet.<UDIM>.%04d.exr: a rain state per
 * UDIM tile the mesh's faces use, advanced together; each frame's maps of
 * every tile (-o, --water, --film) are written together or none
 * (soak/staged.h), then every tile's --exposure. As for single UDIM maps,
 * each tile's exposure sees the whole mesh and water does not flow between
 * tiles' maps. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bake_budget.h"
#include "bake_cli.h"
#include "bake_uv_cli.h"
#include "soak/bake_rain.h"
#include "soak/staged.h"

#define CMD "bake rain"

typedef struct udim_frames {
    soak_rain_frames *state[BAKE_UDIM_MAX_TILES];
    int tiles[BAKE_UDIM_MAX_TILES], n;
} udim_frames;

static void destroy_all(udim_frames *u)
{
    for (int t = 0; t < u->n; ++t) soak_rain_frames_destroy(u->state[t]);
}

/* pattern's path for frame (< 0: not a sequence) and tile, staged. */
static soak_status stage_map(soak_staged *stage, const char *pattern, long frame, int tile, const soak_image *img,
                             int float_exr, char *err, size_t errlen)
{
    char framed[4096], path[4096];
    soak_status st = frame < 0 ? (snprintf(framed, sizeof framed, "%s", pattern), SOAK_OK)
                               : soak_bake_frame_path(pattern, (int)frame, framed, sizeof framed);
    if (st == SOAK_OK) st = bake_uv_tile_path(framed, tile, path, sizeof path);
    if (st != SOAK_OK) {
        snprintf(err, errlen, "%s: the name of tile %d is too long", pattern, tile);
        return st;
    }
    return soak_bake_stage(stage, path, img, float_exr, err, errlen);
}

/* One frame of every tile, staged: paths are -o, --exposure, --water, --film. */
static soak_status stage_frame(udim_frames *u, const bake_opts *o, long f, const char *const *paths, soak_staged *stage,
                               char *err, size_t errlen)
{
    soak_bake_exec exec = {(int)o->threads, NULL, NULL};
    soak_status st = SOAK_OK;
    for (int t = 0; t < u->n && st == SOAK_OK; ++t) {
        soak_rain_frame fr;
        st = soak_rain_frames_at(u->state[t], bake_frame_time(o, f), &exec, &fr, err, errlen);
        if (st != SOAK_OK) break;
        const soak_image *imgs[4] = {&fr.wetness, NULL, &fr.water, &fr.film};
        for (int k = 0; k < 4 && st == SOAK_OK; ++k)
            if (paths[k] && imgs[k])
                st = stage_map(stage, paths[k], f, u->tiles[t], imgs[k], o->float_exr, err, errlen);
        soak_rain_frame_free(&fr);
    }
    return st;
}

static int run_sequence(udim_frames *u, const bake_opts *o, const char *const *paths)
{
    cli_progress bar;
    cli_progress_start(&bar, CMD " (UDIM frames)", (double)(o->last - o->first + 1));
    for (long f = o->first; f <= o->last; ++f) {
        char err[4352] = "";
        soak_staged stage;
        soak_staged_init(&stage);
        soak_status st = stage_frame(u, o, f, paths, &stage, err, sizeof err);
        if (st == SOAK_OK) st = soak_staged_commit(&stage, err, sizeof err);
        else soak_staged_abort(&stage);
        if (st != SOAK_OK) {
            cli_progress_finish(&bar);
            cli_error(CMD, "frame %ld: %s", f, err[0] ? err : soak_status_str(st));
            return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
        }
        cli_progress_update(&bar, (double)(f - o->first + 1));
    }
    cli_progress_finish(&bar);
    if (!paths[1]) return SOAK_EXIT_OK;
    char err[4352] = "";
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = SOAK_OK;
    for (int t = 0; t < u->n && st == SOAK_OK; ++t)
        st = stage_map(&stage, paths[1], -1, u->tiles[t], soak_rain_frames_exposure(u->state[t]), o->float_exr, err,
                       sizeof err);
    if (st == SOAK_OK)
        return soak_staged_commit(&stage, err, sizeof err) == SOAK_OK ? SOAK_EXIT_OK : bake_fail(CMD, SOAK_ERR_IO, err);
    soak_staged_abort(&stage);
    return bake_fail(CMD, st, err);
}

/* One rain state per tile; the budget again with every tile's texels. */
static int create_states(udim_frames *u, const soak_mesh *mesh, const soak_rain_params *p, const bake_opts *o,
                         const char *mesh_path, soak_uv_stats *total)
{
    double last_time = fmax(bake_frame_time(o, o->first), bake_frame_time(o, o->last));
    int rc = bake_rain_budget(CMD, p, o->width, o->height * u->n, o->last - o->first + 1, last_time);
    soak_bake_exec exec = {(int)o->threads, NULL, NULL};
    for (int t = 0; t < u->n && !rc; ++t) {
        char err[4352] = "";
        soak_rain_params pt = *p;
        pt.uv.udim_tile = u->tiles[t];
        soak_status st =
            soak_rain_frames_create(mesh, (int)o->width, (int)o->height, &pt, &exec, &u->state[t], err, sizeof err);
        if (st != SOAK_OK) {
            cli_error(CMD, "%s: UDIM tile %d: %s", mesh_path, u->tiles[t], err[0] ? err : soak_status_str(st));
            u->n = t;
            return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
        }
        soak_uv_stats_add(total, soak_rain_frames_uv(u->state[t]));
    }
    if (rc) u->n = 0;
    return rc;
}

int bake_rain_udim_frames(const char *mesh_path, const soak_rain_params *p, const bake_opts *o,
                          const char *const *paths, const bake_uv_opts *uvo)
{
    if (bake_rain_udim_check_paths(paths)) return SOAK_EXIT_USAGE;
    char err[4352] = "";
    soak_mesh mesh;
    soak_status st = soak_mesh_load_uv(mesh_path, &uvo->uv, &mesh, err, sizeof err);
    if (st != SOAK_OK) return bake_fail(CMD, st == SOAK_ERR_ARG ? SOAK_ERR_IO : st, err);
    udim_frames u;
    memset(&u, 0, sizeof u);
    soak_uv_stats total;
    memset(&total, 0, sizeof total);
    int rc = bake_rain_udim_tiles(mesh_path, &mesh, u.tiles, &u.n);
    if (!rc) rc = create_states(&u, &mesh, p, o, mesh_path, &total);
    if (u.n == 0 && !rc) total.faces = (long long)mesh.n_triangles;
    soak_mesh_free(&mesh);
    if (!rc && bake_uv_verdict(CMD, mesh_path, &total, uvo)) rc = SOAK_EXIT_FAIL;
    if (!rc) rc = run_sequence(&u, o, paths);
    if (!rc) {
        printf("%s: frames %ld-%ld, %ldx%ld, in %d UDIM tile%s (%d..%d) from %s\n", o->output, o->first, o->last,
               o->width, o->height, u.n, u.n == 1 ? "" : "s", u.n ? u.tiles[0] : 0, u.n ? u.tiles[u.n - 1] : 0,
               mesh_path);
        bake_uv_report(o->output, &total);
    }
    destroy_all(&u);
    return rc;
}
