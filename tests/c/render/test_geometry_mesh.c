/* Geometry, meshes and threads: meshes read from OBJ files written here,
 * missing UVs and missing files reported; threaded queries agree with
 * single-threaded ones; batched occlusion (Embree packets) agrees with
 * ray-by-ray occlusion (split from test_geometry.c). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "geometry_cases.h"
#include "soak/geometry.h"

static int write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fputs(text, f);
    return fclose(f) == 0;
}

static void test_mesh_files(void)
{
    char dir[] = "/tmp/soak_geom_XXXXXX";
    if (!mkdtemp(dir)) {
        check_true("mkdtemp", 0);
        return;
    }
    char with_uv[300], no_uv[300];
    snprintf(with_uv, sizeof with_uv, "%s/quad_uv.obj", dir);
    snprintf(no_uv, sizeof no_uv, "%s/cube_nouv.obj", dir);
    /* A unit square in z = 0 as one quad face (triangulated to 2) plus one
     * triangle: 3 triangles, UVs on every vertex. */
    write_file(with_uv, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
                        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                        "f 1/1 2/2 3/3 4/4\nf 2/2 5/5 3/3\n");
    /* A cube without texture coordinates: 6 quads = 12 triangles. */
    write_file(no_uv, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    soak_mesh m;
    char err[512] = "";
    check_status("load OBJ with UVs", soak_mesh_load(with_uv, 1, &m, err, sizeof err), SOAK_OK);
    if (m.n_triangles) {
        check_true("3 triangles", m.n_triangles == 3);
        check_true("UVs present", m.uvs != NULL);
        check_true("normals generated", m.normals != NULL);
        soak_geometry *g = NULL;
        soak_geometry_create(&g, err, sizeof err);
        /* Translate by (0,0,-1) and scale z by 2 through xform. */
        double xf[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, -1};
        unsigned id;
        check_status("add mesh", soak_geometry_add_mesh(g, &m, xf, &id), SOAK_OK);
        soak_geometry_commit(g);
        soak_hit h;
        int found;
        soak_ray r = geo_ray(soak_v3(0.25, 0.75, 4), soak_v3(0, 0, -1));
        soak_geometry_intersect(g, &r, &h, &found);
        check_true("mesh hit", found);
        if (found) {
            check_close("mesh t (plane at z=-1)", h.t, 5.0, 1e-12);
            /* OBJ vt maps linearly on the square: uv = (x, y). */
            check_close("mesh uv u", h.u, 0.25, 1e-6);
            check_close("mesh uv v", h.v, 0.75, 1e-6);
            check_close("mesh shading normal +z", h.ns.z, 1.0, 1e-9);
        }
        soak_geometry_destroy(g);
        soak_mesh_free(&m);
    }
    err[0] = '\0';
    check_status("no UVs required", soak_mesh_load(no_uv, 1, &m, err, sizeof err), SOAK_ERR_PARSE);
    printf("  message: %s\n", err);
    check_true("message names file and 'mesh has no UVs'", strstr(err, no_uv) && strstr(err, "mesh has no UVs"));
    check_status("no UVs, not required", soak_mesh_load(no_uv, 0, &m, err, sizeof err), SOAK_OK);
    if (m.n_triangles) {
        check_true("cube 12 triangles", m.n_triangles == 12);
        check_true("cube no UVs", m.uvs == NULL);
        soak_mesh_free(&m);
    }
    /* ASCII PLY: two triangles with per-vertex texture coordinates. */
    char ply[300];
    snprintf(ply, sizeof ply, "%s/tris.ply", dir);
    write_file(
        ply, "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
             "property float s\nproperty float t\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
             "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n3 0 1 2\n3 0 2 3\n");
    check_status("load PLY", soak_mesh_load(ply, 1, &m, err, sizeof err), SOAK_OK);
    if (m.n_triangles) {
        check_true("PLY: 2 triangles, 4 vertices, UVs", m.n_triangles == 2 && m.n_vertices == 4 && m.uvs != NULL);
        soak_mesh_free(&m);
    } else {
        printf("  message: %s\n", err);
    }
    unlink(ply);
    char missing[300];
    snprintf(missing, sizeof missing, "%s/nope.obj", dir);
    err[0] = '\0';
    check_status("missing file", soak_mesh_load(missing, 0, &m, err, sizeof err), SOAK_ERR_IO);
    printf("  message: %s\n", err);
    check_true("missing message names file", strstr(err, missing) != NULL);
    char garbage[300];
    snprintf(garbage, sizeof garbage, "%s/garbage.ply", dir);
    write_file(garbage, "ply\nthis is not a ply file\n");
    err[0] = '\0';
    check_true("garbage file fails", soak_mesh_load(garbage, 0, &m, err, sizeof err) != SOAK_OK);
    printf("  message: %s\n", err);
    check_true("garbage message names file", strstr(err, garbage) != NULL);
    unlink(with_uv);
    unlink(no_uv);
    unlink(garbage);
    rmdir(dir);
}

typedef struct job {
    const soak_geometry *g;
    int n, hits;
    double sum_t;
} job;

static void *worker(void *arg)
{
    job *j = arg;
    for (int i = 0; i < j->n; ++i) {
        double a = 2 * SOAK_PI * i / j->n;
        soak_ray r = geo_ray(soak_v3(3 * cos(a), 3 * sin(a), 0.5 * sin(3 * a)), soak_v3(-cos(a), -sin(a), 0));
        soak_hit h;
        int found;
        if (soak_geometry_intersect(j->g, &r, &h, &found) == SOAK_OK && found) {
            j->hits++;
            j->sum_t += h.t;
        }
    }
    return NULL;
}

static void test_threads(void)
{
    soak_geometry *g = NULL;
    char err[256];
    soak_geometry_create(&g, err, sizeof err);
    soak_geometry_add_sphere(g, soak_v3(0, 0, 0), 1.0, NULL);
    soak_geometry_commit(g);
    job jobs[2] = {{g, 20000, 0, 0}, {g, 20000, 0, 0}};
    pthread_t th[2];
    for (int i = 0; i < 2; ++i) pthread_create(&th[i], NULL, worker, &jobs[i]);
    for (int i = 0; i < 2; ++i) pthread_join(th[i], NULL);
    /* Reference: t = 3 - sqrt(1 - z^2) for z = 0.5 sin(3a), by direct sum. */
    double ref = 0;
    for (int i = 0; i < 20000; ++i) {
        double z = 0.5 * sin(3 * 2 * SOAK_PI * i / 20000);
        ref += 3 - sqrt(1 - z * z);
    }
    for (int i = 0; i < 2; ++i) {
        check_true("thread: every ray hits", jobs[i].hits == 20000);
        check_rel("thread: sum of t vs analytic", jobs[i].sum_t, ref, 1e-12);
    }
    soak_ray rays[3] = {geo_ray(soak_v3(0, 0, -3), soak_v3(0, 0, 1)), geo_ray(soak_v3(5, 5, 5), soak_v3(1, 0, 0)),
                        geo_ray(soak_v3(0, -3, 0), soak_v3(0, 1, 0))};
    soak_hit hits[3];
    int found[3], occ[3];
    check_status("batch intersect", soak_geometry_intersect_n(g, rays, 3, hits, found), SOAK_OK);
    check_true("batch found pattern", found[0] && !found[1] && found[2]);
    check_close("batch t0", hits[0].t, 2.0, 1e-12);
    check_status("batch occluded", soak_geometry_occluded_n(g, rays, 3, occ), SOAK_OK);
    check_true("batch occluded pattern", occ[0] && !occ[1] && occ[2]);
    soak_geometry_destroy(g);
}

/* soak_geometry_occluded_n (packets of rays) against soak_geometry_occluded
 * one ray at a time (Embree's single-ray traversal) on a random triangle soup
 * around a sphere: scattered rays with finite and infinite tfar, and bundles
 * from one origin within a 10 degree cone (the rain bake's), in batches of
 * every size from 1 to 19 and all at once. */
/* A random soup of TRIS triangles in [-1.75, 1.75]^3 around a sphere. */
enum { TRIS = 400 };
static soak_geometry *soup_geometry(const char *label, unsigned long long *s)
{
    soak_geometry *g = NULL;
    char err[256] = "", what[80];
    snprintf(what, sizeof what, "%s: create", label);
    if (!check_status(what, soak_geometry_create(&g, err, sizeof err), SOAK_OK) || !g) return NULL;
    static double pos[9 * TRIS];
    static unsigned idx[3 * TRIS];
    for (int t = 0; t < TRIS; ++t) {
        soak_vec3 c = soak_v3(3 * geo_lcg01(s) - 1.5, 3 * geo_lcg01(s) - 1.5, 3 * geo_lcg01(s) - 1.5);
        for (int k = 0; k < 3; ++k) {
            soak_vec3 v = soak_v3_add(c, soak_v3_scale(geo_unit_dir(s), 0.25));
            pos[9 * t + 3 * k] = v.x, pos[9 * t + 3 * k + 1] = v.y, pos[9 * t + 3 * k + 2] = v.z;
            idx[3 * t + k] = (unsigned)(3 * t + k);
        }
    }
    soak_mesh m = {3 * TRIS, TRIS, pos, NULL, NULL, idx, NULL};
    unsigned id;
    snprintf(what, sizeof what, "%s: add mesh", label);
    check_status(what, soak_geometry_add_mesh(g, &m, NULL, &id), SOAK_OK);
    snprintf(what, sizeof what, "%s: add sphere", label);
    check_status(what, soak_geometry_add_sphere(g, soak_v3(0.2, -0.1, 0.3), 0.4, &id), SOAK_OK);
    snprintf(what, sizeof what, "%s: commit", label);
    check_status(what, soak_geometry_commit(g), SOAK_OK);
    return g;
}

static void test_occluded_batches(void)
{
    enum { RAYS = 3000 };
    unsigned long long s = 2024;
    soak_geometry *g = soup_geometry("batches", &s);
    if (!g) return;
    static soak_ray rays[RAYS];
    static int one[RAYS], all[RAYS], part[RAYS];
    for (int i = 0; i < RAYS; ++i) {
        if (i % 64 == 0 || i < RAYS / 2) { /* a new origin: every ray below RAYS/2, every 64th above */
            rays[i].org = soak_v3(4 * geo_lcg01(&s) - 2, 4 * geo_lcg01(&s) - 2, 4 * geo_lcg01(&s) - 2);
            rays[i].dir = geo_unit_dir(&s);
        } else { /* a bundle: the origin of ray i - 1, the direction within 10 degrees of it */
            rays[i].org = rays[i - 1].org;
            rays[i].dir = soak_v3_norm(soak_v3_add(rays[i - 1].dir, soak_v3_scale(geo_unit_dir(&s), 0.09)));
        }
        rays[i].tnear = geo_lcg01(&s) < 0.5 ? 0.0 : 0.05;
        rays[i].tfar = geo_lcg01(&s) < 0.5 ? INFINITY : 0.2 + 3 * geo_lcg01(&s);
    }
    int bad = 0, hits = 0;
    for (int i = 0; i < RAYS; ++i) {
        bad += soak_geometry_occluded(g, &rays[i], &one[i]) != SOAK_OK;
        hits += one[i];
    }
    check_true("batches: ray-by-ray queries succeed", bad == 0);
    check_true("batches: both answers are common (10-90 % occluded)", hits > RAYS / 10 && hits < 9 * RAYS / 10);
    check_status("batches: all rays in one call", soak_geometry_occluded_n(g, rays, RAYS, all), SOAK_OK);
    int differ = 0;
    for (int i = 0; i < RAYS; ++i) differ += all[i] != one[i];
    char what[160];
    snprintf(what, sizeof what, "batches: one call = ray by ray (%d of %d rays differ)", differ, RAYS);
    check_true(what, differ == 0);
    differ = 0;
    for (int size = 1; size <= 19; ++size) {
        memset(part, 0xFF, sizeof part);
        for (int i = 0; i < RAYS; i += size) {
            int n = RAYS - i < size ? RAYS - i : size;
            bad += soak_geometry_occluded_n(g, rays + i, (size_t)n, part + i) != SOAK_OK;
        }
        for (int i = 0; i < RAYS; ++i) differ += part[i] != one[i];
    }
    snprintf(what, sizeof what, "batches of 1..19 rays = ray by ray (%d answers differ, %d calls failed)", differ, bad);
    check_true(what, differ == 0 && bad == 0);
    soak_ray broken[3] = {rays[0], rays[1], rays[2]};
    broken[1].dir = soak_v3(NAN, 0, 1);
    check_status("batches: a NaN direction in a batch refused", soak_geometry_occluded_n(g, broken, 3, part),
                 SOAK_ERR_ARG);
    check_status("batches: an empty batch", soak_geometry_occluded_n(g, rays, 0, NULL), SOAK_OK);
    soak_geometry_destroy(g);
}

/* soak_geometry_occluded_fan (rays from one origin, tnear 0, tfar infinite:
 * the rain bake's) against soak_geometry_occluded one ray at a time on the
 * soup: FANS origins with a bundle of PER rays each (within ~10 degrees of a
 * random axis, or scattered over the sphere for every fourth origin), asked
 * in calls of every size from 1 to 19 and a whole fan at once. */
static void test_occluded_fan(void)
{
    enum { FANS = 60, PER = 50 };
    unsigned long long s = 77;
    soak_geometry *g = soup_geometry("fan", &s);
    if (!g) return;
    static soak_vec3 org[FANS], dirs[FANS][PER];
    static int one[FANS][PER], got[FANS][PER];
    int bad = 0, hits = 0;
    for (int f = 0; f < FANS; ++f) {
        org[f] = soak_v3(4 * geo_lcg01(&s) - 2, 4 * geo_lcg01(&s) - 2, 4 * geo_lcg01(&s) - 2);
        soak_vec3 axis = geo_unit_dir(&s);
        for (int k = 0; k < PER; ++k) {
            dirs[f][k] =
                f % 4 == 3 ? geo_unit_dir(&s) : soak_v3_norm(soak_v3_add(axis, soak_v3_scale(geo_unit_dir(&s), 0.18)));
            soak_ray r = {org[f], dirs[f][k], 0.0, INFINITY};
            bad += soak_geometry_occluded(g, &r, &one[f][k]) != SOAK_OK;
            hits += one[f][k];
        }
    }
    check_true("fan: ray-by-ray queries succeed", bad == 0);
    check_true("fan: both answers are common (10-90 % occluded)", hits > FANS * PER / 10 && hits < 9 * FANS * PER / 10);
    int differ = 0;
    for (int size = 1; size <= PER; size = size < 19 ? size + 1 : PER) {
        memset(got, 0xFF, sizeof got);
        for (int f = 0; f < FANS; ++f)
            for (int k = 0; k < PER; k += size) {
                int n = PER - k < size ? PER - k : size;
                bad += soak_geometry_occluded_fan(g, org[f], dirs[f] + k, (size_t)n, got[f] + k) != SOAK_OK;
            }
        for (int f = 0; f < FANS; ++f)
            for (int k = 0; k < PER; ++k) differ += got[f][k] != one[f][k];
        if (size == PER) break;
    }
    char what[160];
    snprintf(what, sizeof what, "fan: calls of 1..19 and %d rays agree with ray-by-ray (%d of %d differ, %d failed)",
             PER, differ, 20 * FANS * PER, bad);
    check_true(what, differ == 0 && bad == 0);
    soak_vec3 broken[3] = {dirs[0][0], soak_v3(NAN, 0, 1), dirs[0][2]};
    check_status("fan: a NaN direction refused", soak_geometry_occluded_fan(g, org[0], broken, 3, got[0]),
                 SOAK_ERR_ARG);
    broken[1] = soak_v3(0, 0, 0);
    check_status("fan: a zero direction refused", soak_geometry_occluded_fan(g, org[0], broken, 3, got[0]),
                 SOAK_ERR_ARG);
    check_status("fan: a NaN origin refused",
                 soak_geometry_occluded_fan(g, soak_v3(0, INFINITY, 0), dirs[0], 3, got[0]), SOAK_ERR_ARG);
    check_status("fan: an empty fan", soak_geometry_occluded_fan(g, org[0], NULL, 0, NULL), SOAK_OK);
    check_status("fan: no geometry", soak_geometry_occluded_fan(NULL, org[0], dirs[0], 1, got[0]), SOAK_ERR_NULL);
    soak_geometry_destroy(g);
}

int main(void)
{
    test_mesh_files();
    test_threads();
    test_occluded_batches();
    test_occluded_fan();
    return check_finish();
}
