#define _GNU_SOURCE
#include "fuzz_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* One private folder per process, removed at exit (test code: process-wide
 * state is fine here). */
#define MAX_NAMED 8
static char dir[256];
static char files[MAX_NAMED + 1][300];

static void cleanup(void)
{
    for (int i = 0; i <= MAX_NAMED; ++i)
        if (files[i][0]) unlink(files[i]);
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

static const char *write_to(char *file, size_t cap, const char *name, const uint8_t *data, size_t size)
{
    if (!fuzz_temp_dir()) return NULL;
    if (file[0]) unlink(file);
    snprintf(file, cap, "%s/%s", dir, name);
    FILE *f = fopen(file, "wb");
    if (!f) return NULL;
    int bad = size && fwrite(data, 1, size, f) != size;
    if (fclose(f) != 0 || bad) return NULL;
    return file;
}

const char *fuzz_temp_file(const uint8_t *data, size_t size, const char *ext)
{
    char name[64];
    snprintf(name, sizeof name, "in.%s", ext);
    return write_to(files[MAX_NAMED], sizeof files[MAX_NAMED], name, data, size);
}

const char *fuzz_temp_named(const char *name, const uint8_t *data, size_t size)
{
    int slot = -1;
    for (int i = 0; i < MAX_NAMED && slot < 0; ++i) {
        const char *slash = strrchr(files[i], '/');
        if (!files[i][0] || (slash && !strcmp(slash + 1, name))) slot = i;
    }
    if (slot < 0) return NULL;
    return write_to(files[slot], sizeof files[slot], name, data, size);
}

static void check_printable(const char *err)
{
    if (!err[0]) {
        fprintf(stderr, "fuzz: a failure left its message empty\n");
        abort();
    }
    for (const unsigned char *c = (const unsigned char *)err; *c; ++c)
        if ((*c < 0x20 && *c != '\n' && *c != '\t') || *c == 0x7f) {
            fprintf(stderr, "fuzz: message holds control byte 0x%02x: %s\n", *c, err);
            abort();
        }
}

void fuzz_check_message(const char *err, const char *path, const char *other)
{
    check_printable(err);
    if (strstr(err, path) || (other && strstr(err, other))) return;
    fprintf(stderr, "fuzz: message does not name %s%s%s: %s\n", path, other ? " or " : "", other ? other : "", err);
    abort();
}

void fuzz_check_message_text(const char *err)
{
    check_printable(err);
    if (strchr(err, '\'') || strchr(err, '"') || strchr(err, '.') || strstr(err, "line") || strstr(err, "offset"))
        return;
    fprintf(stderr, "fuzz: message names neither a field nor a position: %s\n", err);
    abort();
}
