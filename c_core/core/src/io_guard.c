/* Input/output identity checks; see soak/io_guard.h. */
#define _POSIX_C_SOURCE 200809L
#include "soak/io_guard.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

void soak_io_guard_init(soak_io_guard *g)
{
    memset(g, 0, sizeof *g);
}

void soak_io_guard_free(soak_io_guard *g)
{
    if (!g) return;
    for (int i = 0; i < g->count; ++i) {
        free(g->files[i].path);
        free(g->files[i].role);
    }
    free(g->files);
    soak_io_guard_init(g);
}

static soak_status add(soak_io_guard *g, const char *role, const char *path, int output)
{
    if (!g) return SOAK_ERR_NULL;
    if (!path || !*path) return SOAK_OK;
    if (g->count == g->capacity) {
        int cap = g->capacity ? 2 * g->capacity : 16;
        soak_io_file *f = realloc(g->files, (size_t)cap * sizeof *f);
        if (!f) return SOAK_ERR_NOMEM;
        g->files = f;
        g->capacity = cap;
    }
    soak_io_file *f = &g->files[g->count];
    f->path = strdup(path);
    f->role = strdup(role ? role : "");
    f->output = output;
    if (!f->path || !f->role) {
        free(f->path);
        free(f->role);
        return SOAK_ERR_NOMEM;
    }
    g->count++;
    return SOAK_OK;
}

soak_status soak_io_guard_input(soak_io_guard *g, const char *role, const char *path)
{
    return add(g, role, path, 0);
}

soak_status soak_io_guard_output(soak_io_guard *g, const char *role, const char *path)
{
    return add(g, role, path, 1);
}

/* stat() follows symbolic links: a link to an input has the input's inode. */
static int same_file(const struct stat *a, const char *path)
{
    struct stat b;
    return stat(path, &b) == 0 && a->st_dev == b.st_dev && a->st_ino == b.st_ino;
}

soak_status soak_io_guard_check(const soak_io_guard *g, char *err, size_t errlen)
{
    if (!g) return SOAK_ERR_NULL;
    for (int i = 0; i < g->count; ++i) {
        const soak_io_file *o = &g->files[i];
        struct stat so;
        if (!o->output || stat(o->path, &so) != 0) continue;
        for (int k = 0; k < g->count; ++k) {
            const soak_io_file *in = &g->files[k];
            if (k == i || (in->output && k > i) || !same_file(&so, in->path)) continue;
            if (err && errlen)
                snprintf(err, errlen, "%s '%s' is the same file as the %s%s%s '%s'; refusing to overwrite it",
                         o->role, o->path, in->output ? "output" : "input", in->role[0] ? " " : "", in->role,
                         in->path);
            return SOAK_ERR_ARG;
        }
    }
    return SOAK_OK;
}

soak_status soak_io_check_output(const char *role, const char *output, const char *const *inputs, int n_inputs,
                                 char *err, size_t errlen)
{
    soak_io_guard g;
    soak_io_guard_init(&g);
    soak_status st = soak_io_guard_output(&g, role, output);
    for (int i = 0; i < n_inputs && st == SOAK_OK; ++i) st = soak_io_guard_input(&g, "", inputs[i]);
    if (st == SOAK_OK) st = soak_io_guard_check(&g, err, errlen);
    soak_io_guard_free(&g);
    return st;
}
