/* Finding the data folder; the search order is in soak/data_dir.h. */
#define _GNU_SOURCE
#include "soak/data_dir.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "self_path.h"

/* Compiled in by CMake: the source and build trees (rule 3). */
#ifndef SOAK_SOURCE_DIR
#define SOAK_SOURCE_DIR ""
#endif
#ifndef SOAK_BUILD_DIR
#define SOAK_BUILD_DIR ""
#endif

/* Rule 2: beside the executable's folder. */
#define SOAK_DATA_INSTALL_DIR "/share/soak"

typedef struct search {
    char tried[2048]; /* the folders looked at, for the message */
} search;

static void note_tried(search *s, const char *what, const char *dir)
{
    size_t used = strlen(s->tried);
    snprintf(s->tried + used, sizeof s->tried - used, "%s%s%s", used ? ", " : "", what, dir);
}

static int holds_marker(const char *dir)
{
    char path[PATH_MAX + 32];
    int w = snprintf(path, sizeof path, "%s/%s", dir, SOAK_DATA_MARKER);
    return w > 0 && (size_t)w < sizeof path && access(path, R_OK) == 0;
}

/* PREFIX/share/soak for the program file PREFIX/bin/soak ("" if unknown). */
static void installed_dir(char *dir, size_t n)
{
    soak_self_file(dir, n);
    soak_path_dirname(dir);
    soak_path_dirname(dir);
    if (!dir[0]) return;
    if (strcmp(dir, "/") == 0) dir[0] = '\0';
    if (strlen(dir) + sizeof SOAK_DATA_INSTALL_DIR > n) dir[0] = '\0';
    else strcat(dir, SOAK_DATA_INSTALL_DIR);
}

/* 1 when the program file lies inside the build tree it was built in. */
static int runs_from_build_tree(void)
{
    char build[PATH_MAX], self[PATH_MAX];
    if (!SOAK_BUILD_DIR[0] || !realpath(SOAK_BUILD_DIR, build)) return 0;
    soak_self_file(self, sizeof self);
    size_t n = strlen(build);
    return strncmp(self, build, n) == 0 && self[n] == '/';
}

static soak_status join(const char *dir, const char *relative, char *out, size_t n, char *err, size_t errlen)
{
    size_t dl = strlen(dir), rl = strlen(relative);
    if (dl + 1 + rl < n) {
        memcpy(out, dir, dl);
        out[dl] = '/';
        memcpy(out + dl + 1, relative, rl + 1);
        return SOAK_OK;
    }
    if (err && errlen) snprintf(err, errlen, "data file path %s/%s is too long", dir, relative);
    return SOAK_ERR_ARG;
}

/* Rule 3: "scenes/..." and "povray/..." from the repository's folders,
 * everything else from c_core/data. */
static soak_status source_path(const char *relative, char *out, size_t n, char *err, size_t errlen)
{
    int top = strncmp(relative, "scenes/", 7) == 0 || strncmp(relative, "povray/", 7) == 0;
    return join(top ? SOAK_SOURCE_DIR : SOAK_SOURCE_DIR "/c_core/data", relative, out, n, err, errlen);
}

static soak_status not_found(const search *s, char *err, size_t errlen)
{
    if (err && errlen)
        snprintf(err, errlen,
                 "no Soak data folder (one holding %s) found; tried %s. Install Soak (cmake --install, or the "
                 ".deb), or set SOAK_DATA_DIR to the folder holding %s",
                 SOAK_DATA_MARKER, s->tried, SOAK_DATA_MARKER);
    return SOAK_ERR_NOT_FOUND;
}

soak_status soak_data_path(const char *relative, char *out, size_t n, char *err, size_t errlen)
{
    if (!relative || !out || n == 0) return SOAK_ERR_NULL;
    search s = {.tried = ""};
    const char *env = getenv("SOAK_DATA_DIR");
    if (env && env[0]) {
        if (holds_marker(env)) return join(env, relative, out, n, err, errlen);
        note_tried(&s, "$SOAK_DATA_DIR=", env);
        return not_found(&s, err, errlen);
    }
    char dir[PATH_MAX];
    installed_dir(dir, sizeof dir);
    if (dir[0] && holds_marker(dir)) return join(dir, relative, out, n, err, errlen);
    note_tried(&s, "", dir[0] ? dir : "(the executable's folder is unknown)");
    if (runs_from_build_tree()) {
        if (holds_marker(SOAK_SOURCE_DIR "/c_core/data")) return source_path(relative, out, n, err, errlen);
        note_tried(&s, "", SOAK_SOURCE_DIR "/c_core/data");
    }
    return not_found(&s, err, errlen);
}
