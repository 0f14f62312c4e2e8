/* Where the running program's code lives; see self_path.h. */
#define _GNU_SOURCE
#include "self_path.h"

#include <inttypes.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* The file mapped at addr according to /proc/self/maps ("" if none). */
static void file_mapped_at(uintptr_t addr, char *path, size_t n)
{
    path[0] = '\0';
    FILE *f = fopen("/proc/self/maps", "re");
    if (!f) return;
    char line[PATH_MAX + 128];
    while (fgets(line, sizeof line, f)) {
        uintptr_t lo = 0, hi = 0;
        int name_at = 0;
        if (sscanf(line, "%" SCNxPTR "-%" SCNxPTR " %*s %*s %*s %*s %n", &lo, &hi, &name_at) < 2 || name_at == 0)
            continue;
        if (addr < lo || addr >= hi) continue;
        const char *name = line + name_at;
        if (name[0] == '/') {
            snprintf(path, n, "%s", name);
            path[strcspn(path, "\n")] = '\0';
        }
        break;
    }
    fclose(f);
}

static void exe_file(char *path, size_t n)
{
    path[0] = '\0';
    if (n < 2) return;
    ssize_t len = readlink("/proc/self/exe", path, n - 1);
    path[len > 0 ? len : 0] = '\0';
}

void soak_self_file(char *path, size_t n)
{
    if (!path || n == 0) return;
    file_mapped_at((uintptr_t)&soak_self_file, path, n);
    if (!path[0]) exe_file(path, n);
}

void soak_path_dirname(char *path)
{
    char *slash = strrchr(path, '/');
    if (!slash) path[0] = '\0';
    else if (slash == path) path[1] = '\0';
    else *slash = '\0';
}

void soak_self_exe_dir(char *dir, size_t n)
{
    if (!dir || n == 0) return;
    exe_file(dir, n);
    soak_path_dirname(dir);
}
