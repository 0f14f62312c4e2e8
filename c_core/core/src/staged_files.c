/* Staged output files; see soak/staged.h. */
#define _GNU_SOURCE
#include "soak/staged.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "soak/image.h"

static void set_err(char *err, size_t errlen, const char *fmt, const char *a, const char *b)
{
    if (err && errlen) snprintf(err, errlen, fmt, a, b);
}

void soak_staged_init(soak_staged *s)
{
    memset(s, 0, sizeof *s);
}

static void free_all(soak_staged *s)
{
    for (int i = 0; i < s->count; ++i) {
        soak_staged_file *f = &s->files[i];
        if (f->fd >= 0) close(f->fd);
        if (f->named) unlink(f->named);
        free(f->named);
        free(f->dst);
    }
    free(s->files);
    soak_staged_init(s);
}

static const char *base_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* The folder part of path ("." when none, "/" for the root). */
static void dir_of(const char *path, char *dir, size_t n)
{
    const char *slash = strrchr(path, '/');
    if (!slash) snprintf(dir, n, ".");
    else if (slash == path) snprintf(dir, n, "/");
    else snprintf(dir, n, "%.*s", (int)(slash - path), path);
}

soak_status soak_path_check_writable(const char *path, char *err, size_t errlen)
{
    if (!path || !*path) {
        set_err(err, errlen, "%soutput path is empty%s", "", "");
        return SOAK_ERR_ARG;
    }
    const char *base = base_of(path);
    if (!*base || !strcmp(base, ".") || !strcmp(base, "..")) {
        set_err(err, errlen, "%s: names a folder, not a file%s", path, "");
        return SOAK_ERR_ARG;
    }
    if (base[0] == '.' && !strchr(base + 1, '.')) {
        set_err(err, errlen, "%s: no file name before the extension '%s'", path, base);
        return SOAK_ERR_ARG;
    }
    char dir[PATH_MAX];
    if (strlen(path) >= sizeof dir) {
        set_err(err, errlen, "%.200s...: output path too long%s", path, "");
        return SOAK_ERR_ARG;
    }
    dir_of(path, dir, sizeof dir);
    struct stat sb;
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
        set_err(err, errlen, "%s: output folder '%s' does not exist", path, dir);
        return SOAK_ERR_IO;
    }
    if (access(dir, W_OK) != 0) {
        set_err(err, errlen, "%s: output folder '%s' is not writable", path, dir);
        return SOAK_ERR_IO;
    }
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode)) {
        set_err(err, errlen, S_ISDIR(sb.st_mode) ? "%s: is a folder, not a file%s"
                                                 : "%s: exists and is not a regular file%s", path, "");
        return SOAK_ERR_ARG;
    }
    return soak_image_output_ready(path, err, errlen);
}

soak_status soak_output_path_check(const char *path, char *err, size_t errlen)
{
    return soak_path_check_writable(path, err, errlen);
}

/* dst itself, or the file a symbolic link dst points to (malloc'ed). */
static soak_status resolve(const char *dst, char **out, char *err, size_t errlen)
{
    struct stat lb;
    *out = NULL;
    if (dst && *dst && lstat(dst, &lb) == 0 && S_ISLNK(lb.st_mode)) {
        *out = realpath(dst, NULL);
        if (!*out) {
            set_err(err, errlen, "%s: is a symbolic link to a missing file (%s)", dst, strerror(errno));
            return SOAK_ERR_IO;
        }
        return SOAK_OK;
    }
    *out = strdup(dst ? dst : "");
    return *out ? SOAK_OK : SOAK_ERR_NOMEM;
}

static soak_status grow(soak_staged *s)
{
    if (s->count < s->capacity) return SOAK_OK;
    int cap = s->capacity ? 2 * s->capacity : 8;
    soak_staged_file *f = realloc(s->files, (size_t)cap * sizeof *f);
    if (!f) return SOAK_ERR_NOMEM;
    s->files = f;
    s->capacity = cap;
    return SOAK_OK;
}

static char *named_temp(const char *dst, int index)
{
    const char *base = base_of(dst);
    size_t n = strlen(dst) + 64;
    char *tmp = malloc(n);
    if (tmp) snprintf(tmp, n, "%.*s.%s.tmp%ld.%d", (int)(base - dst), dst, base, (long)getpid(), index);
    return tmp;
}

/* An anonymous file in dst's folder, or -1 when the file system or /proc
 * does not allow one. */
static int anonymous_file(const char *dst, char *proc, size_t n)
{
#ifdef O_TMPFILE
    char dir[PATH_MAX];
    dir_of(dst, dir, sizeof dir);
    int fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (fd < 0) return -1;
    snprintf(proc, n, "/proc/self/fd/%d", fd);
    if (access(proc, F_OK) != 0) {
        close(fd);
        return -1;
    }
    return fd;
#else
    (void)dst, (void)proc, (void)n;
    return -1;
#endif
}

soak_status soak_staged_add(soak_staged *s, const char *dst, const char **tmp_out, char *err, size_t errlen)
{
    if (!s || !dst || !tmp_out) return SOAK_ERR_NULL;
    char *real = NULL;
    soak_status st = resolve(dst, &real, err, errlen);
    if (st == SOAK_OK) st = soak_path_check_writable(real, err, errlen);
    if (st == SOAK_OK) st = grow(s);
    if (st != SOAK_OK) {
        free(real);
        return st;
    }
    soak_staged_file *f = &s->files[s->count];
    memset(f, 0, sizeof *f);
    f->dst = real;
    f->fd = anonymous_file(real, f->proc, sizeof f->proc);
    if (f->fd < 0) {
        f->named = named_temp(real, s->count);
        if (!f->named) {
            free(real);
            return SOAK_ERR_NOMEM;
        }
        f->fd = open(f->named, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (f->fd < 0) {
            set_err(err, errlen, "%s: cannot create a temporary file: %s", dst, strerror(errno));
            free(f->named);
            free(real);
            return SOAK_ERR_IO;
        }
    }
    s->count++;
    *tmp_out = f->named ? f->named : f->proc;
    return SOAK_OK;
}

soak_status soak_staged_open(soak_staged *s, const char *dst, FILE **f, char *err, size_t errlen)
{
    if (!f) return SOAK_ERR_NULL;
    *f = NULL;
    const char *tmp = NULL;
    soak_status st = soak_staged_add(s, dst, &tmp, err, errlen);
    if (st != SOAK_OK) return st;
    int fd = dup(s->files[s->count - 1].fd);
    *f = fd >= 0 ? fdopen(fd, "wb") : NULL;
    if (!*f) {
        set_err(err, errlen, "%s: cannot create file: %s", dst, strerror(errno));
        if (fd >= 0) close(fd);
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

soak_status soak_staged_close(FILE *f, const char *dst, char *err, size_t errlen)
{
    if (!f) return SOAK_ERR_NULL;
    int bad = fflush(f) != 0 || ferror(f);
    int e = errno;
    if (fclose(f) != 0 && !bad) bad = 1, e = errno;
    if (bad) {
        set_err(err, errlen, "%s: write failed: %s", dst, strerror(e));
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

soak_status soak_staged_write(soak_staged *s, const char *dst, const void *data, size_t len, char *err,
                              size_t errlen)
{
    const char *tmp = NULL;
    soak_status st = soak_staged_add(s, dst, &tmp, err, errlen);
    if (st != SOAK_OK) return st;
    int fd = s->files[s->count - 1].fd;
    const char *p = data;
    while (len > 0) {
        ssize_t w = write(fd, p, len);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            set_err(err, errlen, "%s: write failed: %s", dst, strerror(w < 0 ? errno : ENOSPC));
            return SOAK_ERR_IO;
        }
        p += w;
        len -= (size_t)w;
    }
    return SOAK_OK;
}

/* Gives an anonymous temporary f a hidden name in its folder. */
static soak_status name_temporary(soak_staged_file *f, int index, char *err, size_t errlen)
{
    if (f->named) return SOAK_OK;
    char *name = named_temp(f->dst, index);
    if (!name) return SOAK_ERR_NOMEM;
    if (linkat(AT_FDCWD, f->proc, AT_FDCWD, name, AT_SYMLINK_FOLLOW) != 0) {
        set_err(err, errlen, "%s: cannot name the finished file: %s", f->dst, strerror(errno));
        free(name);
        return SOAK_ERR_IO;
    }
    f->named = name;
    return SOAK_OK;
}

/* Gives named temporary f its final name. */
static soak_status publish(soak_staged_file *f, char *err, size_t errlen)
{
    if (rename(f->named, f->dst) != 0) {
        set_err(err, errlen, "%s: cannot move into place: %s", f->dst, strerror(errno));
        return SOAK_ERR_IO;
    }
    free(f->named);
    f->named = NULL;
    return SOAK_OK;
}

/* A set of several outputs: its renames listed in a journal on disk
 * first (staged_journal.c), so that a run killed between two renames is
 * completed by the next run of the same outputs. *journal is "" for one
 * output. */
static soak_status journal_renames(const soak_staged *s, char *journal, size_t n, char *err, size_t errlen)
{
    journal[0] = '\0';
    if (s->count < 2) return SOAK_OK;
    const char **named = malloc(2 * (size_t)s->count * sizeof *named);
    if (!named) return SOAK_ERR_NOMEM;
    const char **dst = named + s->count;
    for (int i = 0; i < s->count; ++i) named[i] = s->files[i].named, dst[i] = s->files[i].dst;
    soak_status st = soak_staged_journal_name(s->files[0].dst, (long)getpid(), journal, n)
                         ? soak_staged_journal_write(journal, named, dst, s->count, err, errlen)
                         : SOAK_ERR_ARG;
    if (st == SOAK_ERR_ARG) set_err(err, errlen, "%s: the journal's name is too long%s", s->files[0].dst, "");
    if (st != SOAK_OK) journal[0] = '\0';
    free(named);
    return st;
}

soak_status soak_staged_commit(soak_staged *s, char *err, size_t errlen)
{
    for (int i = 0; i < s->count; ++i) {
        if (fsync(s->files[i].fd) != 0) {
            set_err(err, errlen, "%s: write failed: %s", s->files[i].dst, strerror(errno));
            free_all(s);
            return SOAK_ERR_IO;
        }
    }
    /* Every output is complete on disk: only a rename can fail from here
     * (files already renamed then stay complete, the rest are removed).
     * SIGINT, SIGTERM, SIGHUP and SIGQUIT wait until every file has its
     * name: between naming a temporary and renaming it, or between two
     * outputs of one set, a signal left a temporary or a mixed set (issue
     * 51 item 4: 5 of 1591 kills). SIGKILL cannot wait: the next run of the
     * same outputs removes the temporaries it leaves and completes a
     * journalled set (c_core/cli/output_plan.c). */
    sigset_t stop, before;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT), sigaddset(&stop, SIGTERM), sigaddset(&stop, SIGHUP), sigaddset(&stop, SIGQUIT);
    int masked = pthread_sigmask(SIG_BLOCK, &stop, &before) == 0;
    soak_status st = SOAK_OK;
    char journal[PATH_MAX + NAME_MAX + 32];
    for (int i = 0; i < s->count && st == SOAK_OK; ++i) st = name_temporary(&s->files[i], i, err, errlen);
    if (st == SOAK_OK) st = journal_renames(s, journal, sizeof journal, err, errlen);
    for (int i = 0; i < s->count && st == SOAK_OK; ++i) st = publish(&s->files[i], err, errlen);
    if (journal[0]) unlink(journal); /* done, or its temporaries go with free_all */
    free_all(s);
    if (masked) pthread_sigmask(SIG_SETMASK, &before, NULL);
    return st;
}

void soak_staged_abort(soak_staged *s)
{
    free_all(s);
}
