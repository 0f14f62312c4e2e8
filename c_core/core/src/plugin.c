/* Finding and opening the I/O modules; see soak/plugin.h. */
#define _GNU_SOURCE
#include "soak/plugin.h"

#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "self_path.h"

#ifndef SOAK_PLUGIN_BUILD_DIR
#define SOAK_PLUGIN_BUILD_DIR ""
#endif

#define MAX_DIRS 5
/* The modules' folder of an installed copy, relative to its executable's. */
#define SOAK_PLUGIN_INSTALL_DIR "/../lib/soak"

typedef struct dir_list {
    int n;
    char dir[MAX_DIRS][PATH_MAX];
} dir_list;

static void add_dir(dir_list *l, const char *dir, size_t len)
{
    if (len == 0 || len >= PATH_MAX || l->n >= MAX_DIRS) return;
    for (int i = 0; i < l->n; ++i)
        if (strlen(l->dir[i]) == len && !memcmp(l->dir[i], dir, len)) return;
    memcpy(l->dir[l->n], dir, len);
    l->dir[l->n][len] = '\0';
    l->n++;
}

static void add_dir_of(dir_list *l, const char *file)
{
    const char *slash = strrchr(file, '/');
    if (slash) add_dir(l, file, slash == file ? 1 : (size_t)(slash - file));
}

static void search_dirs(dir_list *l)
{
    l->n = 0;
    const char *env = getenv("SOAK_PLUGIN_DIR");
    if (env && *env) {
        add_dir(l, env, strlen(env));
        return;
    }
    char path[PATH_MAX];
    soak_self_file(path, sizeof path);
    add_dir_of(l, path);
    soak_self_exe_dir(path, sizeof path);
    add_dir(l, path, strlen(path));
    /* An installed copy: PREFIX/bin/soak, its modules in PREFIX/lib/soak. */
    soak_self_file(path, sizeof path);
    soak_path_dirname(path);
    if (path[0] && strlen(path) + sizeof SOAK_PLUGIN_INSTALL_DIR < sizeof path) {
        strcat(path, SOAK_PLUGIN_INSTALL_DIR);
        add_dir(l, path, strlen(path));
    }
    add_dir(l, SOAK_PLUGIN_BUILD_DIR, strlen(SOAK_PLUGIN_BUILD_DIR));
}

/* The message names the module, then why (at most 1200 characters of it). */
static void fail(soak_plugin_slot *s, const char *why, const char *more)
{
    s->status = SOAK_ERR_UNSUPPORTED;
    snprintf(s->message, sizeof s->message, "cannot load the %s module %s: %.600s%.600s", s->what, s->file, why, more);
}

void soak_plugin_slot_fill(soak_plugin_slot *s)
{
    dir_list dirs;
    search_dirs(&dirs);
    char tried[1024] = "";
    for (int i = 0; i < dirs.n; ++i) {
        char path[PATH_MAX + 64];
        snprintf(path, sizeof path, "%s/%s", dirs.dir[i], s->file);
        if (access(path, F_OK) != 0) {
            size_t used = strlen(tried);
            snprintf(tried + used, sizeof tried - used, "%s%s", used ? ", " : "", dirs.dir[i]);
            continue;
        }
        void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            const char *why = dlerror();
            fail(s, why ? why : "dlopen failed", "");
            return;
        }
        /* The handle stays open until exit: the table points into it. */
        const void *table = dlsym(h, s->symbol);
        if (!table) {
            fail(s, path, ": no table of this version of soak in it (a module of another version)");
            return;
        }
        s->table = table;
        s->status = SOAK_OK;
        return;
    }
    char where[700];
    snprintf(where, sizeof where, "not found in %.600s", tried[0] ? tried : "any folder");
    fail(s, where,
         " (it is built next to the soak executable and installed in PREFIX/lib/soak; SOAK_PLUGIN_DIR names "
         "another folder)");
}

const void *soak_plugin_slot_table(const soak_plugin_slot *s, char *err, size_t errlen)
{
    if (s->table) return s->table;
    if (err && errlen) snprintf(err, errlen, "%s", s->message[0] ? s->message : "module not loaded");
    return NULL;
}
