/* Scene loader from a path (soak_scene_load) over what a path can be
 * (issue 35): byte 0 picks the kind, modulo 7 --
 *   0 a regular file holding the rest of the input,
 *   1 a FIFO (must be refused, never block),
 *   2 a sparse file: bytes 1-4 (big-endian) give its size in KiB (up to
 *     4 GiB), the rest is written at its start (over SOAK_MAX_SCENE_MB it
 *     must be refused; within it, the holes are NUL bytes and refused),
 *   3 /dev/zero (a device: refused, never read without end),
 *   4 a folder,
 *   5 a symbolic link to /dev/zero,
 *   6 a symbolic link to a regular file holding the rest;
 * every failure's message is printable and names the path. */
#define _GNU_SOURCE
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fuzz_common.h"
#include "soak/scene.h"

static int write_file(const char *path, const uint8_t *data, size_t size, long long total)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) return -1;
    int bad = size && write(fd, data, size) != (ssize_t)size;
    if (!bad && total > (long long)size) bad = ftruncate(fd, (off_t)total) != 0;
    return close(fd) != 0 || bad ? -1 : 0;
}

/* Makes the kind's path; *must_fail when no content could make it load. */
static int make_input(int kind, const char *path, const char *target, const uint8_t *data, size_t size,
                      int *must_fail)
{
    *must_fail = kind >= 1 && kind <= 5;
    switch (kind) {
    case 0: return write_file(path, data, size, 0);
    case 1: return mkfifo(path, 0600);
    case 2: {
        if (size < 4) return -1;
        long long kib = (long long)data[0] << 24 | data[1] << 16 | data[2] << 8 | data[3];
        return write_file(path, data + 4, size - 4, (kib & 0x3fffff) * 1024);
    }
    case 3: return 0; /* the device itself is loaded below */
    case 4: return mkdir(path, 0700);
    case 5: return symlink("/dev/zero", path);
    default: return write_file(target, data, size, 0) || symlink(target, path);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > (1 << 20)) return 0;
    const char *dir = fuzz_temp_dir();
    if (!dir) return 0;
    int kind = data[0] % 7;
    char path[512], target[512];
    snprintf(path, sizeof path, "%s/scene_file.json", dir);
    snprintf(target, sizeof target, "%s/scene_target.json", dir);
    int must_fail = 0;
    if (make_input(kind, path, target, data + 1, size - 1, &must_fail) != 0) goto done;
    const char *load = kind == 3 ? "/dev/zero" : path;
    soak_scene scene;
    char err[1024] = "";
    soak_status st = soak_scene_load(load, &scene, err, sizeof err);
    if (st == SOAK_OK) {
        if (must_fail) {
            fprintf(stderr, "fuzz: %s of kind %d loaded\n", load, kind);
            abort();
        }
        soak_scene_free(&scene);
    } else {
        fuzz_check_message(err, load, NULL);
    }
done:
    unlink(path);
    rmdir(path);
    unlink(target);
    return 0;
}
