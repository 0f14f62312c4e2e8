/* The input policy of soak/input_file.h. */
#define _GNU_SOURCE
#include "soak/input_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

typedef struct kind_info {
    const char *name, *env;
    double default_mib;
} kind_info;

static const kind_info kinds[SOAK_INPUT_KINDS] = {
    {"scene file", "SOAK_MAX_SCENE_MB", 16},   {"presets file", "SOAK_MAX_PRESETS_MB", 16},
    {"image", "SOAK_MAX_IMAGE_MB", 2048},      {"mesh file", "SOAK_MAX_MESH_MB", 2048},
    {"volume file", "SOAK_MAX_VOLUME_MB", 8192},
};

static const kind_info *info(soak_input_kind kind)
{
    return &kinds[(unsigned)kind < SOAK_INPUT_KINDS ? kind : SOAK_INPUT_SCENE];
}

const char *soak_input_kind_name(soak_input_kind kind)
{
    return info(kind)->name;
}

const char *soak_input_kind_env(soak_input_kind kind)
{
    return info(kind)->env;
}

long long soak_input_cap(soak_input_kind kind)
{
    const kind_info *k = info(kind);
    double mib = k->default_mib;
    const char *e = getenv(k->env);
    if (e && *e) {
        char *end = NULL;
        double user = strtod(e, &end);
        if (*end == '\0' && soak_in_range(user, 1.0, 1e7)) mib = user;
    }
    return (long long)(mib * 1048576.0);
}

long long soak_input_stored_bytes(long long size, long long blocks)
{
    long long stored = blocks * 512;
    return size > 65536 && stored >= 0 && stored < size ? stored : size;
}

static soak_status say(char *err, size_t errlen, soak_status st, const char *fmt, const char *path, const char *what,
                       const char *detail)
{
    if (err && errlen) {
        snprintf(err, errlen, fmt, path, what, detail);
        soak_message_printable(err);
    }
    return st;
}

static const char *not_regular(mode_t m)
{
    if (S_ISDIR(m)) return "a folder";
    if (S_ISFIFO(m)) return "a FIFO (pipe)";
    if (S_ISSOCK(m)) return "a socket";
    if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
    return "not a regular file";
}

/* What is wrong with a file of this status as an input of this kind, or
 * SOAK_OK; *total accumulates sizes counted against the cap. */
static soak_status judge(const char *path, const struct stat *sb, soak_input_kind kind, const char *role,
                         long long *total, char *err, size_t errlen)
{
    const char *what = role ? role : info(kind)->name;
    if (!S_ISREG(sb->st_mode))
        return say(err, errlen, SOAK_ERR_IO, "%s: cannot read this %s: it is %s, not a regular file", path, what,
                   not_regular(sb->st_mode));
    long long cap = soak_input_cap(kind), sum = (long long)sb->st_size + (total ? *total : 0);
    if (total) *total = sum;
    if (sum <= cap) return SOAK_OK;
    if (err && errlen) {
        snprintf(err, errlen, "%s: this %s is %lld bytes%s; the limit for a %s is %lld MiB (%s raises it)", path, what,
                 (long long)sb->st_size, total && sum != (long long)sb->st_size ? " (with the files counted before it)" : "",
                 info(kind)->name, cap / 1048576, info(kind)->env);
        soak_message_printable(err);
    }
    return SOAK_ERR_ARG;
}

/* Opens path without blocking after checking what it is; the open file is
 * checked again (the name may have changed in between). */
static soak_status open_input(const char *path, soak_input_kind kind, const char *role, long long *total, int *fd,
                              long long *size, char *err, size_t errlen)
{
    const char *what = role ? role : info(kind)->name;
    struct stat sb;
    if (stat(path, &sb) != 0)
        return say(err, errlen, SOAK_ERR_IO, "%s: cannot open this %s (%s)", path, what, strerror(errno));
    long long before = total ? *total : 0;
    soak_status st = judge(path, &sb, kind, role, total, err, errlen);
    if (st != SOAK_OK) return st;
    *fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (*fd < 0) return say(err, errlen, SOAK_ERR_IO, "%s: cannot open this %s (%s)", path, what, strerror(errno));
    if (total) *total = before;
    if (fstat(*fd, &sb) != 0) st = say(err, errlen, SOAK_ERR_IO, "%s: cannot read this %s (%s)", path, what, strerror(errno));
    else st = judge(path, &sb, kind, role, total, err, errlen);
    if (st != SOAK_OK) {
        close(*fd);
        *fd = -1;
        return st;
    }
    if (size) *size = (long long)sb.st_size;
    return SOAK_OK;
}

soak_status soak_input_check_part(const char *path, soak_input_kind kind, const char *role, long long *total,
                                  char *err, size_t errlen)
{
    if (!path || !total) return SOAK_ERR_NULL;
    int fd = -1;
    soak_status st = open_input(path, kind, role, total, &fd, NULL, err, errlen);
    if (fd >= 0) close(fd);
    return st;
}

soak_status soak_input_check(const char *path, soak_input_kind kind, long long *size, char *err, size_t errlen)
{
    if (!path) return SOAK_ERR_NULL;
    int fd = -1;
    long long n = 0;
    soak_status st = open_input(path, kind, NULL, NULL, &fd, &n, err, errlen);
    if (fd >= 0) close(fd);
    if (st == SOAK_OK && size) *size = n;
    return st;
}

/* Reads exactly want bytes, then checks that nothing follows. */
static soak_status read_exact(int fd, const char *path, const char *what, char *buf, size_t want, char *err,
                              size_t errlen)
{
    size_t got = 0;
    for (;;) {
        char probe;
        char *dst = got < want ? buf + got : &probe;
        ssize_t r = read(fd, dst, got < want ? want - got : 1);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) return say(err, errlen, SOAK_ERR_IO, "%s: read error in this %s (%s)", path, what, strerror(errno));
        if (r == 0) break;
        if (got >= want)
            return say(err, errlen, SOAK_ERR_IO, "%s: this %s grew while it was read%s", path, what,
                       " (it is read up to the size it had when opened)");
        got += (size_t)r;
    }
    if (got == want) return SOAK_OK;
    if (err && errlen) {
        snprintf(err, errlen, "%s: short read: %zu of the %zu bytes of this %s (did it shrink while it was read?)", path,
                 got, want, what);
        soak_message_printable(err);
    }
    return SOAK_ERR_IO;
}

soak_status soak_input_read(const char *path, soak_input_kind kind, char **text, size_t *n, char *err,
                            size_t errlen)
{
    if (!path || !text) return SOAK_ERR_NULL;
    *text = NULL;
    if (n) *n = 0;
    int fd = -1;
    long long size = 0;
    soak_status st = open_input(path, kind, NULL, NULL, &fd, &size, err, errlen);
    if (st != SOAK_OK) return st;
    char *buf = malloc((size_t)size + 1);
    if (!buf) {
        close(fd);
        if (err && errlen) {
            snprintf(err, errlen, "%s: out of memory for the %lld bytes of this %s", path, size, info(kind)->name);
            soak_message_printable(err);
        }
        return SOAK_ERR_NOMEM;
    }
    st = read_exact(fd, path, info(kind)->name, buf, (size_t)size, err, errlen);
    close(fd);
    if (st != SOAK_OK) {
        free(buf);
        return st;
    }
    buf[size] = '\0';
    *text = buf;
    if (n) *n = (size_t)size;
    return SOAK_OK;
}
