#define _GNU_SOURCE
#include "fuzz_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* One private folder per process, removed at exit (test code: process-wide
 * state is fine here). */
static char dir[256];
static char file[300];

static void cleanup(void)
{
    if (file[0]) unlink(file);
    if (dir[0]) rmdir(dir);
}

const char *fuzz_temp_dir(void)
{
    if (!dir[0]) {
        const char *base = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : (getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
        snprintf(dir, sizeof dir, "%s/soak_fuzz.XXXXXX", base);
        if (!mkdtemp(dir)) {
            dir[0] = '\0';
            return NULL;
        }
        atexit(cleanup);
    }
    return dir;
}

const char *fuzz_temp_file(const uint8_t *data, size_t size, const char *ext)
{
    if (!fuzz_temp_dir()) return NULL;
    if (file[0]) unlink(file);
    snprintf(file, sizeof file, "%s/in.%s", dir, ext);
    FILE *f = fopen(file, "wb");
    if (!f) return NULL;
    int bad = size && fwrite(data, 1, size, f) != size;
    if (fclose(f) != 0 || bad) return NULL;
    return file;
}
