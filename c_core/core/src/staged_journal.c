/* The journal of a set of outputs being renamed (soak/staged.h): the one
 * window in which a set is neither the old nor the new is between its
 * first and its last rename, and SIGKILL there leaves a mixed set (issue
 * 51 item 4). Before the first rename, the set's finished temporaries and
 * their final names are written beside the first output and flushed to
 * disk; after the last, the journal is removed. A later run of the same
 * outputs that finds a journal of a process that is gone completes the
 * renames, so the set is the killed run's, whole. */
#define _DEFAULT_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "soak/staged.h"

#define JOURNAL_MAGIC "soak-staged-journal 1"
/* Two absolute paths per file, NUL-terminated, for at most a few outputs:
 * a larger file is not a journal of ours. */
#define JOURNAL_MAX_BYTES (64 * (2 * PATH_MAX + 2))

/* path as an absolute name in its folder's canonical form (the folder
 * resolved, the name kept), or 0 when the folder does not resolve. */
static int absolute_in_folder(const char *path, char *out, size_t n)
{
    const char *slash = strrchr(path, '/');
    char dir[PATH_MAX], real[PATH_MAX];
    if (!slash) snprintf(dir, sizeof dir, ".");
    else if (slash == path) snprintf(dir, sizeof dir, "/");
    else snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    if (!realpath(dir, real)) return 0;
    int w = snprintf(out, n, "%s/%s", strcmp(real, "/") ? real : "", slash ? slash + 1 : path);
    return w > 0 && (size_t)w < n;
}

int soak_staged_journal_name(const char *dst, long pid, char *out, size_t n)
{
    const char *slash = strrchr(dst, '/');
    int w =
        snprintf(out, n, "%.*s.%s.journal%ld", slash ? (int)(slash - dst) + 1 : 0, dst, slash ? slash + 1 : dst, pid);
    return w > 0 && (size_t)w < n;
}

static int write_all_fd(int fd, const char *p, size_t len)
{
    while (len) {
        ssize_t w = write(fd, p, len);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return 0;
        p += w;
        len -= (size_t)w;
    }
    return 1;
}

soak_status soak_staged_journal_write(const char *journal, const char *const *named, const char *const *dst, int n,
                                      char *err, size_t errlen)
{
    int fd = open(journal, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    int ok = fd >= 0 && write_all_fd(fd, JOURNAL_MAGIC, sizeof JOURNAL_MAGIC);
    for (int i = 0; ok && i < n; ++i) {
        char a[PATH_MAX + NAME_MAX + 2], b[PATH_MAX + NAME_MAX + 2];
        ok = absolute_in_folder(named[i], a, sizeof a) && absolute_in_folder(dst[i], b, sizeof b) &&
             write_all_fd(fd, a, strlen(a) + 1) && write_all_fd(fd, b, strlen(b) + 1);
    }
    if (ok) ok = fsync(fd) == 0;
    int saved = errno;
    if (fd >= 0 && close(fd) != 0) ok = 0;
    if (ok) return SOAK_OK;
    if (fd >= 0) unlink(journal);
    if (err && errlen)
        snprintf(err, errlen, "%s: cannot write the journal of the outputs' renames: %s", journal, strerror(saved));
    return SOAK_ERR_IO;
}

/* named is "<folder>/.<base>.tmp<digits>.<digits>" for dst "<folder>/<base>":
 * a journal names only temporaries of its own outputs. */
static int temporary_of(const char *named, const char *dst)
{
    const char *ds = strrchr(dst, '/'), *ns = strrchr(named, '/');
    if (!ds || !ns || ds - dst != ns - named || strncmp(dst, named, (size_t)(ds - dst)) != 0) return 0;
    size_t base = strlen(ds + 1);
    const char *t = ns + 1;
    if (t[0] != '.' || strncmp(t + 1, ds + 1, base) != 0 || strncmp(t + 1 + base, ".tmp", 4) != 0) return 0;
    const char *p = t + 1 + base + 4;
    size_t digits = strspn(p, "0123456789");
    if (!digits || p[digits] != '.') return 0;
    p += digits + 1;
    digits = strspn(p, "0123456789");
    return digits && !p[digits];
}

static char *read_small(const char *path, size_t *len)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    struct stat st;
    char *buf = NULL;
    if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size <= JOURNAL_MAX_BYTES &&
        (buf = malloc((size_t)st.st_size + 1)) != NULL) {
        ssize_t r = read(fd, buf, (size_t)st.st_size);
        if (r != st.st_size) {
            free(buf);
            buf = NULL;
        } else {
            buf[r] = '\0';
            *len = (size_t)r;
        }
    }
    if (fd >= 0) close(fd);
    return buf;
}

int soak_staged_journal_recover(const char *journal, int (*planned)(void *ctx, const char *dst), void *ctx)
{
    size_t len = 0;
    char *buf = read_small(journal, &len);
    if (!buf || len < sizeof JOURNAL_MAGIC || memcmp(buf, JOURNAL_MAGIC, sizeof JOURNAL_MAGIC) != 0) {
        free(buf);
        return -1;
    }
    int renamed = 0;
    for (size_t at = sizeof JOURNAL_MAGIC; at < len;) {
        const char *named = buf + at, *dst = named + strlen(named) + 1;
        if (dst >= buf + len) break;
        at = (size_t)(dst - buf) + strlen(dst) + 1;
        if (temporary_of(named, dst) && planned(ctx, dst) && access(named, F_OK) == 0 && rename(named, dst) == 0)
            ++renamed;
    }
    free(buf);
    unlink(journal);
    return renamed;
}
