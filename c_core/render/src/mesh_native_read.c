/* The native reader's entry (mesh_native.h): picks OBJ, PLY or STL by the file's
 * extension, maps the file, reads it with the format's reader, makes the
 * soak_mesh and validates it; anything it declines goes to Assimp. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mesh_import.h"
#include "mesh_native.h"

int soak_mesh_native_enabled(void)
{
    const char *e = getenv("SOAK_MESH_READER");
    return !(e && !strcmp(e, "assimp"));
}

static int format_of(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash)) return 0;
    return !strcasecmp(dot, ".obj") ? 1 : !strcasecmp(dot, ".ply") ? 2 : !strcasecmp(dot, ".stl") ? 3 : 0;
}

int soak_mesh_native_read(const char *path, const soak_mesh_request *rq, soak_mesh *mesh, char *why, size_t whylen)
{
    int fmt = format_of(path);
    snprintf(why, whylen, "not OBJ, PLY or STL");
    if (!fmt || !soak_mesh_native_enabled()) return 0;
    if (rq->uv && (rq->uv->uv_index != 0 || rq->uv->uv_name[0])) {
        snprintf(why, whylen, "a UV set other than the first asked for");
        return 0;
    }
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    struct stat sb;
    if (fd < 0 || fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode) || sb.st_size < 8) {
        snprintf(why, whylen, "cannot open or too short (%s)", fd < 0 ? strerror(errno) : "");
        if (fd >= 0) close(fd);
        return 0;
    }
    void *map = mmap(NULL, (size_t)sb.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
    close(fd);
    if (map == MAP_FAILED) {
        snprintf(why, whylen, "cannot map the file (%s)", strerror(errno));
        return 0;
    }
    madvise(map, (size_t)sb.st_size, MADV_SEQUENTIAL);
    native_text t = {map, (const char *)map + sb.st_size};
    native_mesh nm;
    memset(&nm, 0, sizeof nm);
    int ok = fmt == 1   ? native_read_obj(t, &nm, why, whylen)
             : fmt == 2 ? native_read_ply(t, &nm, why, whylen)
                        : native_read_stl(t, &nm, why, whylen);
    munmap(map, (size_t)sb.st_size);
    if (ok) ok = native_finish(&nm, rq, mesh, why, whylen);
    native_mesh_free(&nm);
    if (!ok) return 0;
    char err[256];
    if (soak_mesh_validate(mesh, path, err, sizeof err) != SOAK_OK) {
        snprintf(why, whylen, "%s", err);
        return 0;
    }
    return 1;
}
