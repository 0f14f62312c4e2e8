#define _POSIX_C_SOURCE 200809L
#include "soak/staged_files.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "soak/image.h"

void soak_staged_init(soak_staged *s)
{
    memset(s, 0, sizeof *s);
}

static void free_all(soak_staged *s)
{
    for (int i = 0; i < s->count; ++i) {
        free(s->tmp[i]);
        free(s->dst[i]);
    }
    free(s->tmp);
    free(s->dst);
    soak_staged_init(s);
}

soak_status soak_staged_add(soak_staged *s, const char *dst, const char **tmp_out, char *err, size_t errlen)
{
    if (!s || !dst || !tmp_out) return SOAK_ERR_NULL;
    soak_status st = soak_path_check_writable(dst, err, errlen);
    if (st != SOAK_OK) return st;
    if (s->count == s->capacity) {
        int cap = s->capacity ? 2 * s->capacity : 8;
        char **t = realloc(s->tmp, (size_t)cap * sizeof *t);
        if (!t) return SOAK_ERR_NOMEM;
        s->tmp = t;
        char **d = realloc(s->dst, (size_t)cap * sizeof *d);
        if (!d) return SOAK_ERR_NOMEM;
        s->dst = d;
        s->capacity = cap;
    }
    /* Hidden temporary next to the target: ".<base>.tmp<pid>.<n>" */
    const char *slash = strrchr(dst, '/');
    size_t dirlen = slash ? (size_t)(slash - dst + 1) : 0;
    size_t n = strlen(dst) + 64;
    char *tmp = malloc(n);
    char *cpy = malloc(strlen(dst) + 1);
    if (!tmp || !cpy) {
        free(tmp);
        free(cpy);
        return SOAK_ERR_NOMEM;
    }
    snprintf(tmp, n, "%.*s.%s.tmp%ld.%d", (int)dirlen, dst, dst + dirlen, (long)getpid(), s->count);
    strcpy(cpy, dst);
    s->tmp[s->count] = tmp;
    s->dst[s->count] = cpy;
    s->count++;
    *tmp_out = tmp;
    return SOAK_OK;
}

soak_status soak_staged_open(soak_staged *s, const char *dst, FILE **f, char *err, size_t errlen)
{
    if (!f) return SOAK_ERR_NULL;
    *f = NULL;
    const char *tmp = NULL;
    soak_status st = soak_staged_add(s, dst, &tmp, err, errlen);
    if (st != SOAK_OK) return st;
    *f = fopen(tmp, "wb");
    if (!*f) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot create file: %s", dst, strerror(errno));
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

soak_status soak_staged_close(FILE *f, const char *dst, char *err, size_t errlen)
{
    int bad = ferror(f);
    if (fclose(f) != 0) bad = 1;
    if (bad) {
        if (err && errlen) snprintf(err, errlen, "%s: write failed (disk full?)", dst);
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

soak_status soak_staged_commit(soak_staged *s, char *err, size_t errlen)
{
    for (int i = 0; i < s->count; ++i) {
        if (rename(s->tmp[i], s->dst[i]) != 0) {
            if (err && errlen) snprintf(err, errlen, "%s: cannot move into place: %s", s->dst[i], strerror(errno));
            /* Files already renamed stay complete; the rest are removed. */
            for (int j = i; j < s->count; ++j) remove(s->tmp[j]);
            free_all(s);
            return SOAK_ERR_IO;
        }
    }
    free_all(s);
    return SOAK_OK;
}

void soak_staged_abort(soak_staged *s)
{
    for (int i = 0; i < s->count; ++i) remove(s->tmp[i]);
    free_all(s);
}
