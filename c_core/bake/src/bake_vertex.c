/* Rain wetness per vertex through a generated atlas (soak/bake_vertex.h). */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "soak/bake_vertex.h"
#include "soak/staged.h"

/* The atlas of n triangles: g x g cells of c texels. */
typedef struct atlas {
    long g, c;
} atlas;

static long grid_side(size_t n)
{
    long g = (long)ceil(sqrt((double)n / 2.0));
    if (g < 1) g = 1;
    while ((double)2 * g * g < (double)n) ++g;
    while (g > 1 && (double)2 * (g - 1) * (g - 1) >= (double)n) --g;
    return g;
}

long soak_vertex_atlas_min_side(size_t n_triangles) { return grid_side(n_triangles) * SOAK_VERTEX_CELL_MIN; }

static int layout(size_t n, int width, int height, atlas *a)
{
    a->g = grid_side(n);
    a->c = (width < height ? width : height) / a->g;
    return a->c >= SOAK_VERTEX_CELL_MIN;
}

/* Corner k of triangle t in texel coordinates (X right, Y down). */
static void corner(const atlas *a, size_t t, int k, double *X, double *Y)
{
    static const int lo[3][2] = {{1, 1}, {-3, 1}, {1, -3}}, hi[3][2] = {{-1, -1}, {3, -1}, {-1, 3}};
    const int(*q)[2] = t % 2 ? hi : lo;
    long cell = (long)(t / 2), x0 = (cell % a->g) * a->c, y0 = (cell / a->g) * a->c;
    *X = (double)(x0 + (q[k][0] < 0 ? a->c + q[k][0] : q[k][0]));
    *Y = (double)(y0 + (q[k][1] < 0 ? a->c + q[k][1] : q[k][1]));
}

/* The texel sampled for corner k of triangle t: inside the face, next to
 * the corner (see the header for the distances). */
static size_t sample_texel(const atlas *a, size_t t, int k, int width)
{
    static const int lo[3][2] = {{1, 1}, {-5, 1}, {1, -5}}, hi[3][2] = {{-2, -2}, {4, -2}, {-2, 4}};
    const int(*q)[2] = t % 2 ? hi : lo;
    long cell = (long)(t / 2), x0 = (cell % a->g) * a->c, y0 = (cell / a->g) * a->c;
    long x = x0 + (q[k][0] < 0 ? a->c + q[k][0] : q[k][0]);
    long y = y0 + (q[k][1] < 0 ? a->c + q[k][1] : q[k][1]);
    return (size_t)y * (size_t)width + (size_t)x;
}

static soak_status fail(char *err, size_t errlen, soak_status st, const char *msg)
{
    if (err && errlen) snprintf(err, errlen, "%s", msg);
    return st;
}

static int mesh_ok(const soak_mesh *m)
{
    if (!m->positions || !m->indices || m->n_triangles == 0 || m->n_vertices == 0) return 0;
    for (size_t i = 0; i < 3 * m->n_triangles; ++i)
        if (m->indices[i] >= m->n_vertices) return 0;
    return 1;
}

soak_status soak_vertex_atlas(const soak_mesh *m, int width, int height, soak_mesh *out, char *err, size_t errlen)
{
    if (!m || !out) return SOAK_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (!mesh_ok(m)) return fail(err, errlen, SOAK_ERR_ARG, "mesh has no triangles or an index out of range");
    if (m->n_triangles > UINT_MAX / 3) return fail(err, errlen, SOAK_ERR_ARG, "mesh has too many triangles");
    atlas a;
    if (!(width > 0 && height > 0) || !layout(m->n_triangles, width, height, &a)) {
        if (err && errlen)
            snprintf(err, errlen,
                     "--per-vertex: %zu triangles need a map of at least %ld x %ld texels (%d per face cell); "
                     "raise --width and --height",
                     m->n_triangles, soak_vertex_atlas_min_side(m->n_triangles),
                     soak_vertex_atlas_min_side(m->n_triangles), SOAK_VERTEX_CELL_MIN);
        return SOAK_ERR_ARG;
    }
    size_t nv = 3 * m->n_triangles;
    out->n_vertices = nv;
    out->n_triangles = m->n_triangles;
    out->positions = malloc(3 * nv * sizeof *out->positions);
    out->uvs = malloc(2 * nv * sizeof *out->uvs);
    out->indices = malloc(nv * sizeof *out->indices);
    out->normals = m->normals ? malloc(3 * nv * sizeof *out->normals) : NULL;
    if (!out->positions || !out->uvs || !out->indices || (m->normals && !out->normals)) {
        soak_mesh_free(out);
        return fail(err, errlen, SOAK_ERR_NOMEM, "out of memory for the per-vertex atlas");
    }
    for (size_t t = 0; t < m->n_triangles; ++t)
        for (int k = 0; k < 3; ++k) {
            size_t j = 3 * t + (size_t)k, src = m->indices[j];
            double X, Y;
            corner(&a, t, k, &X, &Y);
            out->indices[j] = (unsigned)j;
            memcpy(out->positions + 3 * j, m->positions + 3 * src, 3 * sizeof *out->positions);
            if (m->normals) memcpy(out->normals + 3 * j, m->normals + 3 * src, 3 * sizeof *out->normals);
            out->uvs[2 * j] = X / width;
            out->uvs[2 * j + 1] = 1.0 - Y / height;
        }
    return SOAK_OK;
}

static double face_area(const soak_mesh *m, size_t t)
{
    const double *p[3];
    for (int k = 0; k < 3; ++k) p[k] = m->positions + 3 * m->indices[3 * t + k];
    double e1[3], e2[3];
    for (int c = 0; c < 3; ++c) e1[c] = p[1][c] - p[0][c], e2[c] = p[2][c] - p[0][c];
    double x = e1[1] * e2[2] - e1[2] * e2[1], y = e1[2] * e2[0] - e1[0] * e2[2], z = e1[0] * e2[1] - e1[1] * e2[0];
    double area = 0.5 * sqrt(x * x + y * y + z * z);
    return soak_is_finite(area) && area > 0.0 ? area : 0.0;
}

soak_status soak_vertex_gather(const soak_mesh *m, const soak_image *map, float *values, size_t *unreached, char *err,
                               size_t errlen)
{
    if (!m || !map || !values || !unreached) return SOAK_ERR_NULL;
    if (!mesh_ok(m)) return fail(err, errlen, SOAK_ERR_ARG, "mesh has no triangles or an index out of range");
    atlas a;
    if (!map->pixels || map->channels != 1 || !layout(m->n_triangles, map->width, map->height, &a))
        return fail(err, errlen, SOAK_ERR_ARG, "the map is not the per-vertex atlas of this mesh");
    double *sum = calloc(2 * m->n_vertices, sizeof *sum);
    if (!sum) return fail(err, errlen, SOAK_ERR_NOMEM, "out of memory for the per-vertex values");
    double *weight = sum + m->n_vertices;
    for (size_t t = 0; t < m->n_triangles; ++t) {
        double area = face_area(m, t);
        if (!(area > 0.0)) continue;
        for (int k = 0; k < 3; ++k) {
            double v = map->pixels[sample_texel(&a, t, k, map->width)];
            if (!soak_is_finite(v)) continue;
            unsigned i = m->indices[3 * t + k];
            sum[i] += area * fmin(1.0, fmax(0.0, v));
            weight[i] += area;
        }
    }
    *unreached = 0;
    for (size_t i = 0; i < m->n_vertices; ++i) {
        double v = weight[i] > 0.0 ? sum[i] / weight[i] : 0.0;
        *unreached += !(weight[i] > 0.0);
        values[i] = (float)(soak_is_finite(v) ? fmin(1.0, fmax(0.0, v)) : 0.0);
    }
    free(sum);
    return SOAK_OK;
}

static const char *extension(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash) ? dot : "";
}

int soak_vertex_path_ok(const char *path)
{
    static const char *const ok[] = {".ply", ".csv", ".gltf", ".glb"};
    for (size_t k = 0; path && k < sizeof ok / sizeof ok[0]; ++k)
        if (!strcasecmp(extension(path), ok[k])) return 1;
    return 0;
}

/* IEC 61966-2-1:1999 sRGB encoding of a linear value in [0, 1], as a byte. */
static int srgb_byte(double linear)
{
    double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
    return (int)lround(255.0 * fmin(1.0, fmax(0.0, v)));
}

static void write_ply(FILE *f, const soak_mesh *m, const float *values)
{
    fprintf(f,
            "ply\nformat ascii 1.0\ncomment soak bake rain --per-vertex: wetness in [0, 1]; red = green = blue = "
            "its sRGB encoding\nelement vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
            "property float wetness\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
            "element face %zu\nproperty list uchar uint vertex_indices\nend_header\n",
            m->n_vertices, m->n_triangles);
    for (size_t i = 0; i < m->n_vertices && !ferror(f); ++i) {
        const double *p = m->positions + 3 * i;
        int g = srgb_byte(values[i]);
        fprintf(f, "%.9g %.9g %.9g %.6g %d %d %d\n", p[0], p[1], p[2], values[i], g, g, g);
    }
    for (size_t t = 0; t < m->n_triangles && !ferror(f); ++t)
        fprintf(f, "3 %u %u %u\n", m->indices[3 * t], m->indices[3 * t + 1], m->indices[3 * t + 2]);
}

static void write_csv(FILE *f, const soak_mesh *m, const float *values)
{
    fprintf(f, "index,x,y,z,wetness\n");
    for (size_t i = 0; i < m->n_vertices && !ferror(f); ++i) {
        const double *p = m->positions + 3 * i;
        fprintf(f, "%zu,%.9g,%.9g,%.9g,%.6g\n", i, p[0], p[1], p[2], values[i]);
    }
}

soak_status soak_vertex_write(const char *path, const soak_mesh *m, const float *values, char *err, size_t errlen)
{
    if (!path || !m || !values) return SOAK_ERR_NULL;
    if (!soak_vertex_path_ok(path)) {
        if (err && errlen) snprintf(err, errlen, "%s: per-vertex output must end in .ply, .csv, .gltf or .glb", path);
        return SOAK_ERR_ARG;
    }
    for (size_t i = 0; i < m->n_vertices; ++i)
        if (!(values[i] >= 0.0f && values[i] <= 1.0f))
            return fail(err, errlen, SOAK_ERR_NUMERIC, "wetness out of [0, 1]");
    const char *ext = extension(path);
    if (!strcasecmp(ext, ".gltf") || !strcasecmp(ext, ".glb"))
        return soak_vertex_write_gltf(path, m, values, !strcasecmp(ext, ".glb"), err, errlen);
    soak_staged stage;
    soak_staged_init(&stage);
    FILE *f = NULL;
    soak_status st = soak_staged_open(&stage, path, &f, err, errlen);
    if (st == SOAK_OK) {
        if (!strcasecmp(extension(path), ".ply")) write_ply(f, m, values);
        else write_csv(f, m, values);
        int bad = ferror(f);
        st = soak_staged_close(f, path, err, errlen);
        if (st == SOAK_OK && bad) {
            if (err && errlen) snprintf(err, errlen, "%s: write failed", path);
            st = SOAK_ERR_IO;
        }
    }
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}
