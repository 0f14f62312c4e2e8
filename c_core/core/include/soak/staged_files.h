/* A set of output files written atomically together: each file is written
 * to a temporary name in its destination folder, and only when every file
 * is complete are they all renamed over their targets. Abort (or a failed
 * commit) removes the temporaries, so a failed bake leaves no output. */
#ifndef SOAK_STAGED_FILES_H
#define SOAK_STAGED_FILES_H

#include <stddef.h>
#include <stdio.h>

#include "soak/status.h"

typedef struct soak_staged {
    int count, capacity;
    char **tmp; /* temporary paths */
    char **dst; /* final paths */
} soak_staged;

void soak_staged_init(soak_staged *s);
/* Reserves a temporary path for dst; *tmp_out points into s (valid until
 * commit/abort). Fails with SOAK_ERR_IO naming the folder when it is not
 * writable. */
soak_status soak_staged_add(soak_staged *s, const char *dst, const char **tmp_out, char *err, size_t errlen);
/* soak_staged_add + fopen("wb"). */
soak_status soak_staged_open(soak_staged *s, const char *dst, FILE **f, char *err, size_t errlen);
/* fclose with error check; names dst in err. */
soak_status soak_staged_close(FILE *f, const char *dst, char *err, size_t errlen);
/* Renames every temporary over its target and frees s. */
soak_status soak_staged_commit(soak_staged *s, char *err, size_t errlen);
/* Removes every temporary and frees s. */
void soak_staged_abort(soak_staged *s);

#endif
