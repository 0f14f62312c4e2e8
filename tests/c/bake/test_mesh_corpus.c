/* The Assimp project's test models (Debian's assimp-testmodels, installed by
 * the set-up's test tier; SOAK_MESH_CORPUS names another folder), file by
 * file through the mesh reader and the rain bake's UV step (issue 47):
 *  - no file crashes or hangs the reader (a reader crash message or the time
 *    limit is a failure);
 *  - every file bakes or is refused with a message naming it;
 *  - no bake of a loaded file ends with an empty map without a warning;
 *  - the facts issue 47 measured with its own corpus run hold: regr01.obj
 *    has UVs on 668 of its 2,710 faces; every triangle of WusonOBJ.obj uses
 *    one UV; 10 of the 12 triangles of BoxTextured.gltf lie outside
 *    [0, 1]^2; Wuson.ply at 128^2 covers 4,835 texels, 4,221 of them under
 *    several triangles; and from the files themselves: box_UTF16BE.obj
 *    (UTF-16, 6 faces, no vt lines) is refused for having no UVs, not for
 *    having no faces; the glTF 1.0 BoxTextured.glb is 33 bytes shorter than
 *    its header says and is refused as truncated; STL files have no UVs;
 *    motion-capture and scene files are refused as such.
 * Bakes at 32 x 32 with one ray and no rain: the reader and the UV step,
 * not the physics. About 7 s of CPU time (2026-12-07); the reader's time
 * limit is raised to 120 s here, since a loaded machine stretches the
 * subdivided AC and .blend models past the default 10 s of wall time.
 * // ctest-label: slow (424 reader processes; minutes in a sanitizer build) */
#define _XOPEN_SOURCE 700
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>

#include "check.h"
#include "soak/bake_rain.h"
#include "soak/geometry.h"

#define MAX_FILES 1024

static const char *const aux[] = {"png", "jpg",  "jpeg", "tga",    "bmp",      "dds", "txt",     "bin",
                                  "mtl", "glsl", "vert", "frag",   "material", "md",  "program", "skeleton",
                                  "uc",  "mesh", "pk3",  "shader", "ppm",      "gif"};

static char *files[MAX_FILES];
static int n_files;

static const char *ext_of(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash) ? dot + 1 : "";
}

static int collect(const char *path, const struct stat *sb, int type, struct FTW *ftw)
{
    (void)sb, (void)ftw;
    const char *ext = ext_of(path);
    if (type != FTW_F || !*ext || strstr(path, "ReferenceImages") || strstr(path, "SourceFiles")) return 0;
    for (size_t i = 0; i < sizeof aux / sizeof *aux; ++i)
        if (!strcasecmp(ext, aux[i])) return 0;
    if (n_files < MAX_FILES) files[n_files++] = strdup(path);
    return 0;
}

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

typedef struct outcome {
    soak_status load, bake;
    char err[4352];
    soak_uv_stats uv;
} outcome;

static void bake_one(const char *path, int size, outcome *o)
{
    soak_mesh m;
    memset(o, 0, sizeof *o);
    o->load = soak_mesh_load_uv(path, NULL, &m, o->err, sizeof o->err);
    if (o->load != SOAK_OK) return;
    soak_rain_params p;
    soak_rain_defaults(&p);
    p.rays = 1;
    p.duration = 0;
    p.gutter = 0;
    soak_rain_result r;
    o->bake = soak_bake_rain(&m, size, size, &p, NULL, &r, o->err, sizeof o->err);
    if (o->bake == SOAK_OK) {
        o->uv = r.uv;
        soak_rain_result_free(&r);
    }
    soak_mesh_free(&m);
}

/* The corpus file whose path ends with tail. */
static const char *find(const char *tail)
{
    size_t n = strlen(tail);
    for (int i = 0; i < n_files; ++i) {
        size_t k = strlen(files[i]);
        if (k >= n && !strcmp(files[i] + k - n, tail)) return files[i];
    }
    return NULL;
}

static void check_file_facts(void)
{
    outcome o;
    const char *f;
    if ((f = find("/OBJ/regr01.obj")) && (bake_one(f, 32, &o), check_status("regr01.obj bakes", o.bake, SOAK_OK))) {
        check_close("regr01.obj: faces", (double)o.uv.faces, 2710, 0);
        check_close("regr01.obj: faces without UVs (issue 47: 668 of 2710 have them)", (double)o.uv.no_uv_faces,
                    2710 - 668, 0);
    }
    if ((f = find("/OBJ/WusonOBJ.obj")) && (bake_one(f, 32, &o), check_status("WusonOBJ.obj bakes", o.bake, SOAK_OK))) {
        check_close("WusonOBJ.obj: every one of 3732 triangles degenerate in UV", (double)o.uv.degenerate_faces, 3732,
                    0);
        check_true("WusonOBJ.obj: the empty map warns", soak_uv_stats_warning(&o.uv, NULL, 0));
    }
    if ((f = find("/glTF2/BoxTextured-glTF/BoxTextured.gltf")) &&
        (bake_one(f, 32, &o), check_status("BoxTextured.gltf bakes", o.bake, SOAK_OK)))
        check_close("BoxTextured.gltf: triangles outside [0,1]^2 (issue 47: 10 of 12)", (double)o.uv.outside_faces, 10,
                    0);
    if ((f = find("/PLY/Wuson.ply")) && (bake_one(f, 128, &o), check_status("Wuson.ply bakes", o.bake, SOAK_OK))) {
        check_close("Wuson.ply at 128^2: covered texels (issue 47: 4835)", (double)o.uv.covered, 4835, 0);
        check_close("Wuson.ply at 128^2: shared texels (issue 47: 4221)", (double)o.uv.shared, 4221, 0);
    }
    if ((f = find("/OBJ/box_UTF16BE.obj"))) {
        bake_one(f, 32, &o);
        check_true("box_UTF16BE.obj: refused for its missing UVs (6 faces, no vt), not for missing faces",
                   o.load != SOAK_OK && strstr(o.err, "mesh has no UVs") != NULL);
    }
    if ((f = find("/glTF/BoxTextured-glTF-Binary/BoxTextured.glb"))) {
        bake_one(f, 32, &o);
        check_true("glTF 1.0 BoxTextured.glb: refused as 33 bytes short of its header's 17754",
                   o.load != SOAK_OK && strstr(o.err, "declares 17754 bytes, the file has 17721") != NULL);
    }
}

/* Every file: an outcome with the right kind of reason. Returns the files
 * that baked a covered texel. */
static int check_every_file(void)
{
    int baked = 0, bad_crash = 0, bad_silent = 0, bad_name = 0, bad_class = 0;
    for (int i = 0; i < n_files; ++i) {
        outcome o;
        const char *ext = ext_of(files[i]);
        bake_one(files[i], 32, &o);
        if (strstr(o.err, "crashed") || strstr(o.err, "did not finish")) {
            printf("  reader failure: %s\n", o.err);
            ++bad_crash;
        }
        if (o.load == SOAK_OK && o.bake == SOAK_OK) {
            baked += o.uv.covered > 0;
            if (o.uv.covered == 0 && !soak_uv_stats_warning(&o.uv, NULL, 0)) {
                printf("  silent empty map: %s\n", files[i]);
                ++bad_silent;
            }
        } else if (!strstr(o.err, files[i])) {
            printf("  message without the file: %s: %s\n", files[i], o.err);
            ++bad_name;
        }
        int no_surface = !strcasecmp(ext, "bvh") || !strcasecmp(ext, "csm") || !strcasecmp(ext, "lws");
        if ((!strcasecmp(ext, "stl") && o.load == SOAK_OK) ||
            (no_surface && !(o.load == SOAK_ERR_UNSUPPORTED && strstr(o.err, "unsupported mesh format: .")))) {
            printf("  wrong class: %s: %s\n", files[i], o.err);
            ++bad_class;
        }
    }
    check_close("corpus: reader crashes or hangs", bad_crash, 0, 0);
    check_close("corpus: empty maps without a warning", bad_silent, 0, 0);
    check_close("corpus: refusals that do not name the file", bad_name, 0, 0);
    check_close("corpus: STL loaded with UVs, or scene/motion files not refused as such", bad_class, 0, 0);
    return baked;
}

int main(void)
{
    const char *root = getenv("SOAK_MESH_CORPUS");
    struct stat sb;
    if (!root || !*root) root = "/usr/share/assimp/models";
    if (stat(root, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
        check_skip("the Assimp test models", "assimp-testmodels not installed (/usr/share/assimp/models)");
        return check_finish();
    }
    setenv("SOAK_MESH_TIMEOUT", "120", 0);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    nftw(root, collect, 16, FTW_PHYS);
    qsort(files, (size_t)n_files, sizeof *files, by_name);
    check_file_facts();
    int baked = check_every_file();
    clock_gettime(CLOCK_MONOTONIC, &t1);
    struct rusage self, kids;
    getrusage(RUSAGE_SELF, &self);
    getrusage(RUSAGE_CHILDREN, &kids);
    double cpu =
        (double)(self.ru_utime.tv_sec + self.ru_stime.tv_sec + kids.ru_utime.tv_sec + kids.ru_stime.tv_sec) +
        1e-6 * (double)(self.ru_utime.tv_usec + self.ru_stime.tv_usec + kids.ru_utime.tv_usec + kids.ru_stime.tv_usec);
    printf("%d files, %d baked a covered map, %.1f s wall, %.1f s CPU\n", n_files, baked,
           (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec), cpu);
    for (int i = 0; i < n_files; ++i) free(files[i]);
    return check_finish();
}
