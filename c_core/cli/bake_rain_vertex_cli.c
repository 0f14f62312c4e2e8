/* soak bake rain MESH --per-vertex OUT: the rain wetness per vertex through
 * a generated atlas (soak/bake_vertex.h), for meshes with or without UVs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_cli.h"
#include "bake_uv_cli.h"
#include "bake_vertex_pov.h"
#include "soak/bake_rain.h"
#include "soak/bake_vertex.h"
#include "soak/io_guard.h"
#include "soak/staged.h"

#define CMD "bake rain"

static void on_progress(void *user, double fraction) { cli_progress_update(user, fraction); }

/* OUT: .ply, .csv, .gltf, .glb or .inc, writable, not the mesh; --pov-name
 * only with .inc, a POV-Ray identifier. 0 or the exit code. */
static int check_out(const char *mesh_path, const char *out, const char *pov_name)
{
    char err[4352] = "";
    const char *inputs[1] = {mesh_path};
    if (!soak_vertex_path_ok(out) && !bake_vertex_pov_path(out)) {
        cli_error(CMD, "--per-vertex '%s': the output must end in .ply, .csv, .gltf, .glb or .inc", out);
        return SOAK_EXIT_USAGE;
    }
    if (pov_name && !bake_vertex_pov_path(out)) {
        cli_error(CMD, "--pov-name is for --per-vertex OUT.inc (the POV-Ray mesh2's name), not '%s'", out);
        return SOAK_EXIT_USAGE;
    }
    if (pov_name && !bake_vertex_pov_name_ok(pov_name)) {
        cli_error(CMD,
                  "--pov-name '%s': a POV-Ray identifier is a capital letter, then letters, digits or _ "
                  "(at most %d)",
                  pov_name, BAKE_VERTEX_POV_NAME_MAX);
        return SOAK_EXIT_USAGE;
    }
    soak_status st = soak_output_path_check(out, err, sizeof err);
    if (st == SOAK_OK) st = soak_io_check_output("--per-vertex", out, inputs, 1, err, sizeof err);
    if (st == SOAK_OK) st = soak_path_check_writable(out, err, sizeof err);
    if (st == SOAK_OK) return 0;
    cli_error(CMD, "--per-vertex: %s", err[0] ? err : soak_status_str(st));
    return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
}

/* The bake of the atlas into res; *atlas_fits 0 when the map is too small
 * for it. */
static soak_status bake_atlas(const char *mesh_path, const soak_mesh *mesh, const soak_rain_params *p,
                              const bake_opts *o, soak_rain_result *res, int *atlas_fits)
{
    char err[4352] = "";
    soak_mesh atlas;
    soak_status st = soak_vertex_atlas(mesh, (int)o->width, (int)o->height, &atlas, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s: %s", mesh_path, err[0] ? err : soak_status_str(st));
        *atlas_fits = st != SOAK_ERR_ARG;
        return st;
    }
    cli_progress bar;
    cli_progress_start(&bar, CMD, 1.0);
    soak_bake_exec exec = {(int)o->threads, on_progress, &bar};
    st = soak_bake_rain(&atlas, (int)o->width, (int)o->height, p, &exec, res, err, sizeof err);
    cli_progress_finish(&bar);
    soak_mesh_free(&atlas);
    if (st != SOAK_OK) cli_error(CMD, "%s: %s", mesh_path, err[0] ? err : soak_status_str(st));
    return st;
}

/* The values, the warning when every one is 0, the file, the report. */
static int gather_and_write(const char *mesh_path, const soak_mesh *mesh, const soak_rain_result *res, const char *out,
                            const char *pov_name, const bake_uv_opts *u)
{
    char err[4352] = "";
    size_t unreached = 0, wet = 0;
    float *values = malloc(mesh->n_vertices * sizeof *values);
    soak_status st =
        values ? soak_vertex_gather(mesh, &res->wetness, values, &unreached, err, sizeof err) : SOAK_ERR_NOMEM;
    double sum = 0.0, lo = 1.0, hi = 0.0;
    for (size_t i = 0; st == SOAK_OK && i < mesh->n_vertices; ++i)
        sum += values[i], wet += values[i] > 0.0f, lo = fmin(lo, values[i]), hi = fmax(hi, values[i]);
    if (st == SOAK_OK && wet == 0) {
        if (u->strict) {
            cli_error(CMD, "%s: every vertex's wetness is 0 (%zu vertices); --strict: nothing written", mesh_path,
                      mesh->n_vertices);
            free(values);
            return SOAK_EXIT_FAIL;
        }
        fprintf(stderr, "soak %s: warning: %s: every vertex's wetness is 0 (%zu vertices): no rain reached them\n", CMD,
                mesh_path, mesh->n_vertices);
    }
    if (st == SOAK_OK && unreached)
        fprintf(stderr, "soak %s: warning: %s: %zu of %zu vertices are on no face with area (wetness 0)\n", CMD,
                mesh_path, unreached, mesh->n_vertices);
    if (st == SOAK_OK && bake_vertex_pov_path(out))
        st = bake_vertex_pov_write(out, mesh, values, mesh_path, pov_name ? pov_name : BAKE_VERTEX_POV_DEFAULT_NAME,
                                   err, sizeof err);
    else if (st == SOAK_OK) st = soak_vertex_write(out, mesh, values, err, sizeof err);
    free(values);
    if (st != SOAK_OK) return bake_fail(CMD, st, err);
    printf("%s: wetness of %zu vertices (%zu faces) from %s: mean %.4g, min %.4g, max %.4g\n", out, mesh->n_vertices,
           mesh->n_triangles, mesh_path, sum / (double)mesh->n_vertices, lo, hi);
    return SOAK_EXIT_OK;
}

int bake_rain_vertex(const char *mesh_path, const soak_rain_params *p, const bake_opts *o, const char *out,
                     const char *pov_name, const bake_uv_opts *u)
{
    int rc = check_out(mesh_path, out, pov_name);
    if (rc) return rc;
    char err[4352] = "";
    soak_mesh mesh;
    soak_status st = soak_mesh_load(mesh_path, 0, &mesh, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    soak_rain_params q = *p;
    q.uv.outside = SOAK_UV_REFUSE; /* the atlas lies in [0, 1]^2; anything else is a bug */
    q.uv.udim_tile = 0;
    soak_rain_result res;
    int atlas_fits = 1;
    if (bake_atlas(mesh_path, &mesh, &q, o, &res, &atlas_fits) != SOAK_OK) {
        soak_mesh_free(&mesh);
        return atlas_fits ? SOAK_EXIT_FAIL : SOAK_EXIT_USAGE;
    }
    rc = bake_uv_dry_verdict(CMD, mesh_path, &res.exposure, &res.uv, u)
             ? SOAK_EXIT_FAIL
             : gather_and_write(mesh_path, &mesh, &res, out, pov_name, u);
    soak_rain_result_free(&res);
    soak_mesh_free(&mesh);
    return rc;
}
