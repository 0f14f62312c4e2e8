/* Mesh import (mesh_import.h): Assimp runs in libsoak_mesh.so, opened on a
 * command's first mesh (soak/plugin.h); what it returns is validated here.
 * soak_mesh_load (mesh_contain.c) opens the module before it forks the
 * reader, so the child only imports. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_import.h"
#include "mesh_plugin.h"
#include "soak/plugin.h"

/* Written once under pthread_once, read-only afterwards (soak/plugin.h). */
static soak_plugin_slot mesh_slot = SOAK_PLUGIN_SLOT(SOAK_MESH_PLUGIN_FILE, SOAK_MESH_PLUGIN_SYMBOL, "mesh reader (Assimp)");

static void mesh_slot_fill(void)
{
    soak_plugin_slot_fill(&mesh_slot);
}

static const soak_mesh_plugin *mesh_plugin(const char *path, char *err, size_t errlen)
{
    pthread_once(&mesh_slot.once, mesh_slot_fill);
    char why[1600];
    const soak_mesh_plugin *p = soak_plugin_slot_table(&mesh_slot, why, sizeof why);
    if (!p && err && errlen) snprintf(err, errlen, "%s: %s", path, why);
    return p;
}

soak_status soak_mesh_reader_open(const char *path, char *err, size_t errlen)
{
    return mesh_plugin(path, err, errlen) ? SOAK_OK : SOAK_ERR_UNSUPPORTED;
}

static void set_err(char *err, size_t errlen, const char *fmt, const char *a, const char *b)
{
    if (err && errlen) snprintf(err, errlen, fmt, a, b);
}

void soak_mesh_free(soak_mesh *m)
{
    if (!m) return;
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->indices);
    free(m->tri_uv);
    memset(m, 0, sizeof *m);
}

soak_status soak_mesh_import(const char *path, int require_uvs, soak_mesh *mesh, char *err, size_t errlen)
{
    soak_mesh_request rq = {require_uvs, NULL};
    return soak_mesh_import_rq(path, &rq, mesh, err, errlen);
}

soak_status soak_mesh_import_rq(const char *path, const soak_mesh_request *rq, soak_mesh *mesh, char *err,
                                size_t errlen)
{
    if (!path || !mesh || !rq) return SOAK_ERR_NULL;
    const soak_mesh_plugin *p = mesh_plugin(path, err, errlen);
    if (!p) return SOAK_ERR_UNSUPPORTED;
    soak_status st = p->import(path, rq, mesh, err, errlen);
    return st == SOAK_OK ? soak_mesh_validate(mesh, path, err, errlen) : st;
}

soak_status soak_mesh_validate(soak_mesh *m, const char *path, char *err, size_t errlen)
{
    const char *why = NULL;
    char buf[96];
    for (size_t i = 0; i < 3 * m->n_vertices && !why; ++i)
        if (!isfinite(m->positions[i])) {
            snprintf(buf, sizeof buf, "vertex %zu has a non-finite coordinate", i / 3 + 1);
            why = buf;
        }
    for (size_t i = 0; m->uvs && i < 2 * m->n_vertices && !why; ++i)
        if (!isfinite(m->uvs[i])) {
            snprintf(buf, sizeof buf, "vertex %zu has a non-finite texture coordinate", i / 2 + 1);
            why = buf;
        }
    for (size_t i = 0; i < 3 * m->n_triangles && !why; ++i)
        if (m->indices[i] >= m->n_vertices) {
            snprintf(buf, sizeof buf, "triangle %zu names vertex %u of %zu", i / 3 + 1, m->indices[i] + 1,
                     m->n_vertices);
            why = buf;
        }
    if (!why) return SOAK_OK;
    set_err(err, errlen, "%s: %s", path, why);
    soak_mesh_free(m);
    return SOAK_ERR_PARSE;
}
