/* The native OBJ/PLY/STL reader (render/src/mesh_native.h) against
 * Assimp, an independent second reader: on meshes written here (grids
 * with and without normals, quads convex and concave, binary PLY in both
 * byte orders, ASCII PLY, decimals of every length and exponents, binary
 * and ASCII STL), on the project's own mesh seeds (tests/fuzz/corpus/mesh
 * and mesh_native) and on every OBJ, PLY and STL of Assimp's test models
 * where installed, every triangle the native reader gives must equal
 * Assimp's (SOAK_MESH_READER=assimp through the contained reader): same
 * count and order, corners' positions and UVs equal as floats, normals
 * within 1e-5; for STL, whose corners Assimp joins by value, the same
 * vertices in the same numbering too. Hostile files (truncated, indices
 * out of range, 2^31 vertices claimed, NaN, a 2 MB line, UTF-16, STL
 * facet counts beyond the file) are declined by the native reader and end
 * exactly as with Assimp alone. */
#define _GNU_SOURCE
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "check.h"
#include "mesh_native.h"
#include "soak/geometry.h"

static char dir[] = "/tmp/soak_native_XXXXXX";

static const char *path_of(const char *name)
{
    static char p[512];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return p;
}

/* Assimp alone, in its contained child (the environment reaches it). */
static soak_status load_assimp(const char *path, int req, soak_mesh *m, char *err, size_t n)
{
    setenv("SOAK_MESH_READER", "assimp", 1);
    soak_status st = soak_mesh_load(path, req, m, err, n);
    unsetenv("SOAK_MESH_READER");
    return st;
}

typedef struct diff {
    double pos, uv, nrm;
    long order; /* the first triangle that differs in more than rounding, or -1 */
} diff;

static diff compare(const soak_mesh *a, const soak_mesh *b)
{
    diff d = {0, 0, 0, -1};
    for (size_t t = 0; t < a->n_triangles && t < b->n_triangles; ++t)
        for (int k = 0; k < 3; ++k) {
            unsigned ia = a->indices[3 * t + k], ib = b->indices[3 * t + k];
            for (int c = 0; c < 3; ++c) {
                d.pos = fmax(d.pos, fabs(a->positions[3 * ia + c] - b->positions[3 * ib + c]));
                d.nrm = fmax(d.nrm, fabs(a->normals[3 * ia + c] - b->normals[3 * ib + c]));
            }
            for (int c = 0; c < 2 && a->uvs && b->uvs; ++c)
                d.uv = fmax(d.uv, fabs(a->uvs[2 * ia + c] - b->uvs[2 * ib + c]));
            if (d.order < 0 && d.pos > 0) d.order = (long)t;
        }
    return d;
}

/* Native (in this process) against Assimp (contained) on one file: 1 when
 * the native reader took it. */
static int equal_to_assimp(const char *path, int req, int strict_normals)
{
    soak_mesh n = {0}, a = {0};
    char why[200] = "", err[600] = "", what[700];
    soak_mesh_request rq = {req, NULL};
    int took = soak_mesh_native_read(path, &rq, &n, why, sizeof why);
    if (!took) printf("info: %s declined: %s\n", path, why);
    if (!took) return 0;
    soak_status st = load_assimp(path, req, &a, err, sizeof err);
    snprintf(what, sizeof what, "%s: Assimp reads what the native reader read (%s)", path, err);
    if (!check_status(what, st, SOAK_OK)) {
        soak_mesh_free(&n);
        return 1;
    }
    diff d = compare(&n, &a);
    snprintf(what, sizeof what, "%s: triangles native %zu = Assimp %zu", path, n.n_triangles, a.n_triangles);
    check_true(what, n.n_triangles == a.n_triangles);
    snprintf(what, sizeof what, "%s: UVs on both or neither", path);
    check_true(what, (n.uvs != NULL) == (a.uvs != NULL));
    snprintf(what, sizeof what, "%s: corner positions equal (max diff %.3g, first differing triangle %ld)", path, d.pos,
             d.order);
    check_true(what, d.pos == 0);
    snprintf(what, sizeof what, "%s: corner UVs equal (max diff %.3g)", path, d.uv);
    check_true(what, d.uv == 0);
    const char *dot = strrchr(path, '.');
    if (dot && !strcasecmp(dot, ".stl")) {
        int same = n.n_vertices == a.n_vertices && n.n_triangles == a.n_triangles &&
                   !memcmp(n.indices, a.indices, 3 * n.n_triangles * sizeof *n.indices) &&
                   !memcmp(n.positions, a.positions, 3 * n.n_vertices * sizeof *n.positions);
        snprintf(what, sizeof what,
                 "%s: vertices joined and numbered as Assimp's, positions the same bits, -0 as +0 (native %zu, "
                 "Assimp %zu)",
                 path, n.n_vertices, a.n_vertices);
        check_true(what, same);
    }
    snprintf(what, sizeof what, "%s: normals within 1e-5 (max diff %.3g)", path, d.nrm);
    if (strict_normals) check_close(what, d.nrm, 0, 1e-5);
    else printf("info: %s\n", what);
    soak_mesh_free(&n);
    soak_mesh_free(&a);
    return 1;
}

/* --- meshes written here --- */

static double height(int i, int j) { return 0.3 * sin(0.37 * i) * cos(0.23 * j) + 0.001 * ((i * 7 + j * 13) % 11); }

/* An N x N grid: normals (vn) or not, quads or triangles, UV indices
 * numbered backwards (v and vt apart), coordinates in a few styles. */
static void write_obj_grid(const char *name, int n, int normals, int quads)
{
    FILE *f = fopen(path_of(name), "w");
    if (!f) return;
    int nv = (n + 1) * (n + 1);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            double x = -1 + 2.0 * i / n, z = 1 - 2.0 * j / n, y = height(i, j);
            if ((i + j) % 3 == 0) fprintf(f, "v %.6f %.17g %.4e\n", x, y, z);
            else fprintf(f, "v  %.9f\t%.6f %.12f\r\n", x, y, z);
        }
    for (int k = nv - 1; k >= 0; --k)
        fprintf(f, "vt %.7f %.5f\n", (k % (n + 1)) / (double)n, (k / (n + 1)) / (double)n);
    if (normals)
        for (int k = 0; k < nv; ++k) fprintf(f, "vn %.4f %.4f %.4f\n", 0.1 * sin(k), 1.0, 0.1 * cos(k));
    fprintf(f, "# faces\ns off\n");
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
            int ta = nv + 1 - a, tb = nv + 1 - b, tc = nv + 1 - c, td = nv + 1 - d;
            if (quads && normals)
                fprintf(f, "f %d/%d/%d %d/%d/%d %d/%d/%d %d/%d/%d\n", a, ta, a, b, tb, b, d, td, d, c, tc, c);
            else if (quads) fprintf(f, "f %d/%d %d/%d %d/%d %d/%d\n", a, ta, b, tb, d, td, c, tc);
            else fprintf(f, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, ta, b, tb, d, td, a, ta, d, td, c, tc);
        }
    fclose(f);
}

/* Darts (concave quads) with the reflex corner at each position, and a
 * plain obj without UVs. */
static void write_obj_darts(const char *name)
{
    FILE *f = fopen(path_of(name), "w");
    if (!f) return;
    const double dart[4][2] = {{0, 0}, {1, 0.3}, {0.35, 0.35}, {0.3, 1}};
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) {
            const double *p = dart[(k + r) % 4];
            fprintf(f, "v %g %g %g\n", p[0] + 2 * r, p[1], 0.01 * k);
        }
    for (int r = 0; r < 4; ++r) fprintf(f, "f %d %d %d %d\n", 4 * r + 1, 4 * r + 2, 4 * r + 3, 4 * r + 4);
    fclose(f);
}

static void put(FILE *f, const void *v, size_t n, int big)
{
    const unsigned char *b = v;
    for (size_t i = 0; i < n; ++i) fputc(b[big ? n - 1 - i : i], f);
}

/* A binary PLY grid: float (LE) or double (BE) coordinates, normals,
 * texture_u/v, a colour byte, triangles and quads mixed, a face flag. */
static void write_ply_grid(const char *name, int n, int big, int with_uv, long cut)
{
    FILE *f = fopen(path_of(name), "wb");
    if (!f) return;
    int nv = (n + 1) * (n + 1), nf = n * n + n * n / 2;
    const char *ct = big ? "double" : "float";
    fprintf(f,
            "ply\nformat binary_%s_endian 1.0\ncomment written by test_mesh_native\nelement vertex %d\n"
            "property %s x\nproperty %s y\nproperty %s z\nproperty float nx\nproperty float ny\nproperty float nz\n",
            big ? "big" : "little", nv, ct, ct, ct);
    if (with_uv) fprintf(f, "property float texture_u\nproperty float texture_v\n");
    fprintf(f,
            "property uchar red\nelement face %d\nproperty list uchar %s vertex_indices\nproperty uchar flags\n"
            "end_header\n",
            nf, big ? "uint" : "int");
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            double p[3] = {-1 + 2.0 * i / n, height(i, j), 1 - 2.0 * j / n};
            float fp[3] = {(float)p[0], (float)p[1], (float)p[2]}, nr[3] = {0.1f * i, 1, 0},
                  uv[2] = {(float)i / n, (float)j / n};
            for (int k = 0; k < 3; ++k) big ? put(f, &p[k], 8, 1) : put(f, &fp[k], 4, 0);
            for (int k = 0; k < 3; ++k) put(f, &nr[k], 4, big);
            for (int k = 0; with_uv && k < 2; ++k) put(f, &uv[k], 4, big);
            fputc(200, f);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            int32_t q[4] = {a, b, d, c}, t1[3] = {a, b, d}, t2[3] = {a, d, c};
            unsigned char k4 = 4, k3 = 3, flag = 1;
            if ((i + j) % 2) {
                put(f, &k4, 1, big);
                for (int k = 0; k < 4; ++k) put(f, &q[k], 4, big);
                put(f, &flag, 1, big);
                continue;
            }
            put(f, &k3, 1, big);
            for (int k = 0; k < 3; ++k) put(f, &t1[k], 4, big);
            put(f, &flag, 1, big);
            put(f, &k3, 1, big);
            for (int k = 0; k < 3; ++k) put(f, &t2[k], 4, big);
            put(f, &flag, 1, big);
        }
    long size = ftell(f);
    fclose(f);
    if (cut > 0 && truncate(path_of(name), size - cut) != 0) check_true("truncate", 0);
}

/* ASCII PLY: Assimp's u/v names, decimals of 1 to 20 digits, exponents,
 * signs, integers, a trailing blank and CR LF line ends. */
static void write_ply_ascii(const char *name)
{
    FILE *f = fopen(path_of(name), "w");
    if (!f) return;
    fprintf(f, "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty double z\n"
               "property float u\nproperty float v\nproperty uchar red\nelement face 3\n"
               "property list uchar int vertex_index\nend_header\n");
    fprintf(f, "0 0 0 0 0 1\n1.5 -0.25 1e-3 0.123456789012345678901 .5 2\n2.25E+1 +3 -1.e2 0.1 0.2 3 \r\n");
    fprintf(f, "-7.000001 0.333333333333333333 12345678.9 1 1 4\n4 5 6 0.75 0.25 5\n1e-40 3.4e5 -0 0.5 0.5 6\n");
    fprintf(f, "3 0 1 2\n4 1 3 4 2\n3 5 0 2\n");
    fclose(f);
}

/* A binary STL of the grid, its left half flat at height -0 or +0 (by
 * facet): the facet normal in float, nudged by -4e-6, 0 or 4e-6 per
 * component (one step apart is within Assimp's 1e-5 join distance, two
 * are not, so the flat half's joins follow that distance and which vertex
 * is found first), or 0 when zero_normals; a header that starts with
 * "solid" (binary by its size all the same), colour bits on some facets.
 * count_extra: facets claimed beyond those written. */
static void write_stl_binary(const char *name, int n, int zero_normals, unsigned count_extra)
{
    FILE *f = fopen(path_of(name), "wb");
    if (!f) return;
    char header[80] = "solid grid written by test_mesh_native COLOR=";
    fwrite(header, 1, 80, f);
    uint32_t count = (uint32_t)(2 * n * n) + count_extra;
    fwrite(&count, 4, 1, f);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            for (int h = 0; h < 2; ++h) {
                int c[3][2] = {{i, j}, {i + 1, j + h}, {i + 1 - h, j + 1}};
                float p[3][3], e1[3], e2[3], nr[3];
                for (int k = 0; k < 3; ++k) {
                    p[k][0] = (float)(-1 + 2.0 * c[k][0] / n), p[k][2] = (float)(1 - 2.0 * c[k][1] / n);
                    p[k][1] = 2 * c[k][0] <= n ? (h ? -0.0f : 0.0f) : (float)(0.2 * height(c[k][0], c[k][1]));
                }
                for (int k = 0; k < 3; ++k) e1[k] = p[1][k] - p[0][k], e2[k] = p[2][k] - p[0][k];
                nr[0] = e1[1] * e2[2] - e1[2] * e2[1], nr[1] = e1[2] * e2[0] - e1[0] * e2[2],
                nr[2] = e1[0] * e2[1] - e1[1] * e2[0];
                float l = sqrtf(nr[0] * nr[0] + nr[1] * nr[1] + nr[2] * nr[2]);
                for (int k = 0; k < 3; ++k)
                    nr[k] = zero_normals ? 0.0f : nr[k] / l + 4e-6f * (float)(((i + j + h) % 3) - 1);
                uint16_t attr = (i + j) % 5 == 0 ? (uint16_t)(0x8000u | 0x1Fu) : 0;
                fwrite(nr, 4, 3, f);
                fwrite(p, 4, 9, f);
                fwrite(&attr, 2, 1, f);
            }
    fclose(f);
}

/* The same grid as plain ASCII STL, numbers in several styles. */
static void write_stl_ascii(const char *name, int n)
{
    FILE *f = fopen(path_of(name), "w");
    if (!f) return;
    fprintf(f, "  solid grid\n");
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            for (int h = 0; h < 2; ++h) {
                int c[3][2] = {{i, j}, {i + 1, j + h}, {i + 1 - h, j + 1}};
                fprintf(f, "facet normal %.6e %d %.3f\r\n  outer loop\r\n", 0.01 * i, 1, -0.02 * j);
                for (int k = 0; k < 3; ++k) {
                    double x = -1 + 2.0 * c[k][0] / n, z = 1 - 2.0 * c[k][1] / n, y = height(c[k][0], c[k][1]);
                    if ((i + k) % 2) fprintf(f, "    vertex %.9f\t%.17g %.4e\r\n", x, y, z);
                    else fprintf(f, "    vertex  %g %.6f %.12f \r\n", x, y, z);
                }
                fprintf(f, "  endloop\r\nendfacet\r\n");
            }
    fprintf(f, "endsolid grid\n\n");
    fclose(f);
}

static void write_text(const char *name, const char *text, size_t n)
{
    FILE *f = fopen(path_of(name), "wb");
    if (!f) return;
    fwrite(text, 1, n, f);
    fclose(f);
}

static void test_written(void)
{
    write_obj_grid("grid_vn.obj", 24, 1, 0);
    write_obj_grid("grid_quads.obj", 24, 0, 1);
    write_obj_grid("grid_tris.obj", 24, 0, 0);
    write_obj_grid("grid_quads_vn.obj", 24, 1, 1);
    write_obj_darts("darts.obj");
    write_ply_grid("grid_le.ply", 24, 0, 1, 0);
    write_ply_grid("grid_be.ply", 24, 1, 0, 0);
    write_ply_ascii("ascii.ply");
    const char *uv[] = {"grid_vn.obj",       "grid_quads.obj", "grid_tris.obj",
                        "grid_quads_vn.obj", "grid_le.ply",    "ascii.ply"};
    write_stl_binary("grid.stl", 24, 0, 0);
    write_stl_binary("zero_normals.stl", 12, 1, 0);
    write_stl_ascii("grid_ascii.stl", 16);
    const char *no_uv[] = {"darts.obj", "grid_be.ply", "grid.stl", "zero_normals.stl", "grid_ascii.stl"};
    char what[300];
    for (size_t i = 0; i < sizeof uv / sizeof *uv; ++i) {
        snprintf(what, sizeof what, "%s: the native reader takes it", uv[i]);
        check_true(what, equal_to_assimp(path_of(uv[i]), SOAK_MESH_UVS_ALL, 1));
    }
    for (size_t i = 0; i < sizeof no_uv / sizeof *no_uv; ++i) {
        snprintf(what, sizeof what, "%s: the native reader takes it", no_uv[i]);
        check_true(what, equal_to_assimp(path_of(no_uv[i]), 0, 1));
    }
}

/* The native reader declines, and soak_mesh_load ends exactly as with
 * Assimp alone: same status, same message. */
static void same_end(const char *name, int req)
{
    soak_mesh n = {0}, a = {0};
    char why[200] = "", e1[700] = "", e2[700] = "", what[1600];
    soak_mesh_request rq = {req, NULL};
    const char *p = path_of(name);
    int took = soak_mesh_native_read(p, &rq, &n, why, sizeof why);
    snprintf(what, sizeof what, "%s: declined by the native reader (%s)", name, why);
    check_true(what, !took);
    soak_mesh_free(&n);
    soak_status s1 = soak_mesh_load(p, req, &n, e1, sizeof e1), s2 = load_assimp(p, req, &a, e2, sizeof e2);
    snprintf(what, sizeof what, "%s: same status (%d, %d) and message as Assimp alone ('%s')", name, s1, s2, e1);
    check_true(what, s1 == s2 && !strcmp(e1, e2) && (s1 != SOAK_OK || n.n_triangles == a.n_triangles));
    printf("info: %s: declined (%s), then status %d: %s\n", name, why, s1, e1);
    soak_mesh_free(&n);
    soak_mesh_free(&a);
}

/* STL: more facets claimed than written (read as ASCII by Assimp for its
 * "solid" header), a count whose size wraps in Assimp's 32-bit check onto
 * the file's size, a cut file, no facets, NaN in binary and ASCII, text
 * after endsolid, and a mesh without UVs where a map needs them. */
static void test_hostile_stl(void)
{
    write_stl_binary("claims_more.stl", 4, 0, 1);
    write_stl_binary("wraps.stl", 1, 0, 2147483648u);
    write_stl_binary("cut.stl", 4, 0, 0);
    if (truncate(path_of("cut.stl"), 84 + 50 * 32 - 7) != 0) check_true("truncate", 0);
    write_stl_binary("no_facets.stl", 0, 0, 0);
    char bin[134] = "binary without a solid header";
    uint32_t one = 1;
    float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, NAN, 0};
    memcpy(bin + 80, &one, 4);
    memcpy(bin + 84, facet, sizeof facet);
    bin[132] = bin[133] = 0;
    write_text("nan.stl", bin, sizeof bin);
    static const char nan_ascii[] = "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\n"
                                    "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n";
    write_text("nan_ascii.stl", nan_ascii, sizeof nan_ascii - 1);
    static const char two[] = "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                              "endloop\nendfacet\nendsolid a\nsolid b\nendsolid b\n";
    write_text("two_solids.stl", two, sizeof two - 1);
    const char *names[] = {"claims_more.stl", "wraps.stl",     "cut.stl",       "no_facets.stl",
                           "nan.stl",         "nan_ascii.stl", "two_solids.stl"};
    for (size_t i = 0; i < sizeof names / sizeof *names; ++i) same_end(names[i], 0);
    write_stl_binary("needs_uv.stl", 2, 0, 0);
    same_end("needs_uv.stl", SOAK_MESH_UVS_ALL);
}

static void test_hostile(void)
{
    write_ply_grid("cut.ply", 8, 0, 1, 37);
    write_text("index_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 32);
    write_text("index_range.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n"
               "0 1 0\n3 0 1 7\n",
               162);
    static const char huge_count[] =
        "ply\nformat binary_little_endian 1.0\nelement vertex 2147483648\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\nproperty list uchar int "
        "vertex_indices\nend_header\n0123456789abcdef";
    write_text("huge_count.ply", huge_count, sizeof huge_count - 1);
    write_text("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 34);
    float nanv[9] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
    char nan_ply[400];
    int h = snprintf(nan_ply, sizeof nan_ply,
                     "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                     "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                     "end_header\n");
    memcpy(nan_ply + h, nanv, sizeof nanv);
    int32_t tri[3] = {0, 1, 2};
    nan_ply[h + sizeof nanv] = 3;
    memcpy(nan_ply + h + sizeof nanv + 1, tri, sizeof tri);
    write_text("nan.ply", nan_ply, (size_t)h + sizeof nanv + 1 + sizeof tri);
    size_t big = 2u << 20;
    char *line = malloc(big + 64);
    if (line) {
        int k = snprintf(line, 64, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1");
        memset(line + k, '0', big);
        memcpy(line + k + big, " 0 0\nf 1 2 3\n", 13);
        write_text("huge_line.obj", line, (size_t)k + big + 13);
        free(line);
    }
    const char *names[] = {"cut.ply", "index_range.obj", "index_range.ply", "huge_count.ply",
                           "nan.obj", "nan.ply",         "huge_line.obj"};
    for (size_t i = 0; i < sizeof names / sizeof *names; ++i) same_end(names[i], 0);
    test_hostile_stl();
}

/* UTF-16 with a byte-order mark: left to Assimp (mesh_convert.c reads it
 * as UTF-16), whose triangles equal the native reading of the same text in
 * UTF-8. */
static void test_utf16(void)
{
    const char *text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 0.5 0\nvt 0.5 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
    size_t n = strlen(text);
    char *u16 = malloc(2 * n + 2);
    if (!u16) return;
    u16[0] = (char)0xFF, u16[1] = (char)0xFE;
    for (size_t i = 0; i < n; ++i) u16[2 + 2 * i] = text[i], u16[3 + 2 * i] = 0;
    write_text("utf16.obj", u16, 2 * n + 2);
    write_text("utf8.obj", text, n);
    free(u16);
    same_end("utf16.obj", SOAK_MESH_UVS_ALL);
    soak_mesh a = {0}, b = {0};
    char err[600] = "";
    soak_status s1 = soak_mesh_load(path_of("utf16.obj"), 1, &a, err, sizeof err);
    soak_status s2 = soak_mesh_load(path_of("utf8.obj"), 1, &b, err, sizeof err);
    diff d = compare(&a, &b);
    check_true("UTF-16 OBJ (Assimp) and its UTF-8 text (native): same 2 triangles, positions and UVs",
               s1 == SOAK_OK && s2 == SOAK_OK && a.n_triangles == 2 && b.n_triangles == 2 && d.pos == 0 && d.uv == 0);
    soak_mesh_free(&a);
    soak_mesh_free(&b);
}

/* Every OBJ, PLY and STL under folder (recursively), or the project's seeds
 * (first byte the format modulo 12: 0 OBJ, 1 PLY, 2 STL; fuzz_mesh.c). */
static void walk_corpus(const char *folder, int seeds, int *seen, int *taken)
{
    DIR *d = opendir(folder);
    if (!d) return;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", folder, e->d_name);
        const char *dot = strrchr(e->d_name, '.');
        if (e->d_type == DT_DIR) {
            walk_corpus(p, seeds, seen, taken);
        } else if (!seeds && dot &&
                   (!strcasecmp(dot, ".obj") || !strcasecmp(dot, ".ply") || !strcasecmp(dot, ".stl"))) {
            ++*seen;
            *taken += equal_to_assimp(p, 0, 0);
        } else if (seeds) {
            FILE *f = fopen(p, "rb");
            char buf[1 << 16];
            size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
            if (f) fclose(f);
            int fmt = n < 2 ? 3 : buf[0] % 12;
            if (fmt < 0 || fmt > 2) continue;
            char name[300];
            snprintf(name, sizeof name, "seed_%s.%s", e->d_name, fmt == 2 ? "stl" : fmt ? "ply" : "obj");
            write_text(name, buf + 1, n - 1);
            ++*seen;
            *taken += equal_to_assimp(path_of(name), 0, 1);
        }
    }
    closedir(d);
}

static void test_corpora(void)
{
    int seen = 0, taken = 0;
    char seeds[1024];
    snprintf(seeds, sizeof seeds, "%s", __FILE__); /* .../tests/c/render/test_mesh_native.c */
    char *at = strstr(seeds, "/tests/c/render/");
    if (at) strcpy(at, "/tests/fuzz/corpus/mesh");
    walk_corpus(seeds, 1, &seen, &taken);
    if (at) strcat(at, "_native"); /* its own seeds: byte 0 the same for obj, ply and stl */
    walk_corpus(seeds, 1, &seen, &taken);
    printf("info: project seeds: %d OBJ/PLY/STL, %d read natively\n", seen, taken);
    check_true("the project's OBJ, PLY and STL seeds: some read natively", seen > 0 && taken > 0);
    seen = taken = 0;
    walk_corpus("/usr/share/assimp/models", 0, &seen, &taken);
    printf("info: Assimp test models: %d OBJ/PLY/STL, %d read natively\n", seen, taken);
    if (seen == 0) check_skip("Assimp's test models", "assimp-testmodels not installed (/usr/share/assimp/models)");
    else check_true("Assimp's OBJ/PLY test models: some read natively", taken > 0);
}

int main(void)
{
    if (!mkdtemp(dir)) return check_true("mkdtemp", 0), check_finish();
    unsetenv("SOAK_MESH_READER");
    test_written();
    test_hostile();
    test_utf16();
    test_corpora();
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) printf("note: could not remove %s\n", dir);
    return check_finish();
}
