/* A set of output files replaced together ("all or none").
 *
 * Each output is first written to an anonymous file in its destination
 * folder (Linux O_TMPFILE: it has no name, so no exit path -- a crash, a
 * signal, SIGKILL -- can leave a temporary behind). Only when every output is
 * complete and flushed to disk (fsync) does commit give each its final name,
 * so a failed or interrupted run leaves the previous outputs untouched. Where
 * the file system has no O_TMPFILE, a hidden ".<name>.tmp<pid>.<n>" file in
 * the same folder is used instead and removed on abort.
 *
 * Output paths: an empty path, a path ending in '/', an existing folder and
 * a name that is only an extension (".exr") are refused. A destination that
 * is a symbolic link is followed: the file it points to is replaced (as a
 * shell redirection or `cp` would), the link stays; a dangling link is an
 * error. Writes that fail -- full disk, file size limit, I/O error -- are
 * reported with the file's name, never as success. */
#ifndef SOAK_STAGED_H
#define SOAK_STAGED_H

#include <stddef.h>
#include <stdio.h>

#include "soak/status.h"

typedef struct soak_staged_file {
    char *dst;   /* final path (a symlink resolved to its target) */
    char *named; /* hidden temporary name, or NULL for an anonymous file */
    int fd;      /* open on the temporary */
    char proc[32]; /* /proc/self/fd/N of an anonymous temporary */
} soak_staged_file;

typedef struct soak_staged {
    int count, capacity;
    soak_staged_file *files;
} soak_staged;

void soak_staged_init(soak_staged *s);
/* Reserves a temporary for dst; *tmp_out (valid until commit/abort) is a path
 * a writer may open and truncate. Fails with SOAK_ERR_IO/ARG naming dst when
 * the path is refused or its folder is not writable. */
soak_status soak_staged_add(soak_staged *s, const char *dst, const char **tmp_out, char *err, size_t errlen);
/* soak_staged_add + a stdio stream on the temporary. */
soak_status soak_staged_open(soak_staged *s, const char *dst, FILE **f, char *err, size_t errlen);
/* fclose with error check (flush included); names dst in err. */
soak_status soak_staged_close(FILE *f, const char *dst, char *err, size_t errlen);
/* soak_staged_add + writes len bytes, every write checked. */
soak_status soak_staged_write(soak_staged *s, const char *dst, const void *data, size_t len, char *err,
                              size_t errlen);
/* Flushes every temporary to disk; if any fails nothing is renamed and every
 * temporary is removed. Then gives each its final name. Frees s. */
soak_status soak_staged_commit(soak_staged *s, char *err, size_t errlen);
/* Removes every temporary and frees s. */
void soak_staged_abort(soak_staged *s);

/* The renames of a set of two or more outputs are journalled
 * (staged_journal.c): ".<first output's name>.journal<pid>" beside the first
 * output lists each finished temporary and its final name (absolute) until
 * the last rename. soak_staged_journal_name writes that name for pid into
 * out (0 when it does not fit); _write creates it (never over an existing
 * file) and flushes it to disk. */
int soak_staged_journal_name(const char *dst, long pid, char *out, size_t n);
soak_status soak_staged_journal_write(const char *journal, const char *const *named, const char *const *dst, int n,
                                      char *err, size_t errlen);
/* Completes the renames a killed run's journal lists, each only when its
 * temporary exists, is a temporary of that output by name, and
 * planned(ctx, final name) is non-zero; then removes the journal. Returns
 * the number of files renamed, or -1 when journal is not a journal of
 * ours (left as it is). */
int soak_staged_journal_recover(const char *journal, int (*planned)(void *ctx, const char *dst), void *ctx);

/* The checks of soak_staged_add on an output path, without creating
 * anything. */
soak_status soak_output_path_check(const char *path, char *err, size_t errlen);

#endif
