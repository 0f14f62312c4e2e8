/* The native reader's last step (mesh_native.h): corners to vertices
 * (one per distinct position/UV/normal triple, as Assimp's
 * JoinIdenticalVertices leaves them up to numbering), the file's normals
 * or Assimp's smooth normals, and the soak_mesh in double. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_native.h"

#define NONE UINT32_MAX

/* Open addressing over ids; a slot holds an id or NONE. */
typedef struct id_table {
    uint32_t *slot;
    size_t mask;
} id_table;

static uint64_t mix3(uint32_t a, uint32_t b, uint32_t c)
{
    uint64_t h =
        (uint64_t)a * 0x9E3779B97F4A7C15ull ^ (uint64_t)b * 0xC2B2AE3D27D4EB4Full ^ (uint64_t)c * 0x165667B19E3779F9ull;
    return h ^ (h >> 29);
}

static int table_make(id_table *t, size_t want)
{
    size_t n = 1024;
    while (n < 2 * want && n < ((size_t)1 << 40)) n *= 2;
    t->slot = malloc(n * sizeof *t->slot);
    t->mask = n - 1;
    if (t->slot) memset(t->slot, 0xFF, n * sizeof *t->slot);
    return t->slot != NULL;
}

/* Vertices from corner triples: vkey[3 v] is vertex v's triple; index[k]
 * corner k's vertex. */
typedef struct vertex_set {
    uint32_t *vkey, *index;
    size_t n;
} vertex_set;

static size_t find_slot(const id_table *t, const uint32_t *vkey, const uint32_t *key)
{
    size_t i = mix3(key[0], key[1], key[2]) & t->mask;
    while (t->slot[i] != NONE && memcmp(vkey + 3 * (size_t)t->slot[i], key, 3 * sizeof *key)) i = (i + 1) & t->mask;
    return i;
}

static int grow_table(id_table *t, const vertex_set *s)
{
    id_table b;
    if (!table_make(&b, 2 * (t->mask + 1))) return 0;
    for (size_t v = 0; v < s->n; ++v) b.slot[find_slot(&b, s->vkey, s->vkey + 3 * v)] = (uint32_t)v;
    free(t->slot);
    *t = b;
    return 1;
}

static int join_corners(const native_mesh *m, vertex_set *s)
{
    size_t nc = 3 * m->n_tri;
    id_table t = {NULL, 0};
    s->vkey = malloc(3 * nc * sizeof *s->vkey);
    s->index = malloc(nc * sizeof *s->index);
    s->n = 0;
    int ok = s->vkey && s->index && table_make(&t, m->n_pos + 1);
    for (size_t k = 0; ok && k < nc; ++k) {
        const uint32_t *key = m->corner + 3 * k;
        size_t i = find_slot(&t, s->vkey, key);
        if (t.slot[i] == NONE) {
            if (s->n >= 0xFFFFFFFEu) {
                ok = 0;
                break;
            }
            memcpy(s->vkey + 3 * s->n, key, 3 * sizeof *key);
            t.slot[i] = (uint32_t)s->n++;
            if (2 * s->n > t.mask && !grow_table(&t, s)) ok = 0;
        }
        s->index[k] = t.slot[find_slot(&t, s->vkey, key)];
    }
    free(t.slot);
    return ok;
}

/* GenVertexNormalsProcess.cpp (Assimp 5.2), after its triangulation: each
 * of Assimp's vertices takes the unit normal of the last triangle naming
 * it; a PLY's vertices are the file's, an OBJ's are the face corners (a
 * quad's first half names one corner the second half does not). val
 * collects those per position index, summed over an OBJ's corners. */
static void face_normals(const native_mesh *m, double *val, unsigned char *used)
{
    for (size_t f = 0; f < m->n_tri; ++f) {
        const uint32_t *c = m->corner + 9 * f;
        const float *a = m->pos + 3 * (size_t)c[0], *b = m->pos + 3 * (size_t)c[3], *d = m->pos + 3 * (size_t)c[6];
        double e1[3], e2[3], n[3];
        for (int k = 0; k < 3; ++k) e1[k] = (double)b[k] - a[k], e2[k] = (double)d[k] - a[k];
        n[0] = e1[1] * e2[2] - e1[2] * e2[1], n[1] = e1[2] * e2[0] - e1[0] * e2[2],
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; ++k) n[k] = l > 0 ? n[k] / l : 0;
        for (int j = 0; j < 3; ++j) {
            if (!m->indexed && m->kind[f] == 1 && j != 1) continue;
            size_t p = c[3 * j];
            used[p] = 1;
            for (int k = 0; k < 3; ++k) val[3 * p + k] = m->indexed ? n[k] : val[3 * p + k] + n[k];
        }
    }
}

/* Positions in cells of side eps, chained per hash slot. */
typedef struct grid {
    uint32_t *head, *next;
    size_t mask;
    float eps, lo[3];
    const float *pos;
} grid;

static void cell_of(const grid *g, const float *p, long long *c)
{
    for (int k = 0; k < 3; ++k) c[k] = (long long)floor(((double)p[k] - g->lo[k]) / g->eps);
}

static size_t cell_slot(const grid *g, const long long *c)
{
    return mix3((uint32_t)c[0], (uint32_t)c[1], (uint32_t)c[2]) & g->mask;
}

/* ComputePositionEpsilon (ProcessHelper.cpp, Assimp 5.2): 1e-4 of the
 * diagonal of the vertices' bounds. */
static int grid_make(grid *g, const native_mesh *m, const unsigned char *used)
{
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t p = 0; p < m->n_pos; ++p)
        for (int k = 0; k < 3 && (used[p] || m->indexed); ++k)
            lo[k] = fminf(lo[k], m->pos[3 * p + k]), hi[k] = fmaxf(hi[k], m->pos[3 * p + k]);
    float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    g->eps = sqrtf(dx * dx + dy * dy + dz * dz) * 1e-4f;
    memcpy(g->lo, lo, sizeof lo);
    g->pos = m->pos;
    id_table t = {NULL, 0};
    g->next = malloc((m->n_pos + 1) * sizeof *g->next);
    if (!g->next || !table_make(&t, m->n_pos)) return 0;
    g->head = t.slot, g->mask = t.mask;
    for (size_t p = 0; p < m->n_pos && g->eps > 0; ++p) {
        if (!used[p] && !m->indexed) continue;
        long long c[3];
        cell_of(g, m->pos + 3 * p, c);
        size_t s = cell_slot(g, c);
        g->next[p] = g->head[s];
        g->head[s] = (uint32_t)p;
    }
    return 1;
}

/* Appends to *list every position within eps of p (Assimp's SpatialSort
 * FindPositions: squared distance below eps squared, in float). */
static int near_positions(const grid *g, size_t p, uint32_t **list, size_t *n, size_t *cap)
{
    long long c[3], d[3], e[3];
    const float *P = g->pos + 3 * p;
    cell_of(g, P, c);
    *n = 0;
    for (int i = 0; i < 27; ++i) {
        d[0] = c[0] + i % 3 - 1, d[1] = c[1] + i / 3 % 3 - 1, d[2] = c[2] + i / 9 - 1;
        for (uint32_t j = g->head[cell_slot(g, d)]; j != NONE; j = g->next[j]) {
            const float *Q = g->pos + 3 * (size_t)j;
            cell_of(g, Q, e);
            float x = Q[0] - P[0], y = Q[1] - P[1], z = Q[2] - P[2];
            if (memcmp(d, e, sizeof d) || !(x * x + y * y + z * z < g->eps * g->eps)) continue;
            if (*n == *cap) {
                uint32_t *b = realloc(*list, (*cap ? 2 * *cap : 64) * sizeof *b);
                if (!b) return 0;
                *list = b, *cap = *cap ? 2 * *cap : 64;
            }
            (*list)[(*n)++] = j;
        }
    }
    return 1;
}

/* The smoothing pass of GenVertexNormalsProcess (no angle limit, Assimp's
 * default 175 degrees): each vertex not yet visited gathers the vertices
 * near it, and all of them take the sum of their normals. */
static int smooth_normals(const native_mesh *m, double *acc)
{
    double *val = calloc(3 * m->n_pos + 1, sizeof *val);
    unsigned char *used = calloc(m->n_pos + 1, 1), *had = calloc(m->n_pos + 1, 1);
    grid g = {NULL, NULL, 0, 0, {0, 0, 0}, NULL};
    uint32_t *list = NULL;
    size_t n = 0, cap = 0;
    int ok = val && used && had;
    if (ok) face_normals(m, val, used);
    ok = ok && grid_make(&g, m, used);
    for (size_t p = 0; ok && p < m->n_pos && g.eps > 0; ++p) {
        if (had[p] || (!used[p] && !m->indexed)) continue;
        ok = near_positions(&g, p, &list, &n, &cap);
        double sum[3] = {0, 0, 0};
        for (size_t i = 0; ok && i < n; ++i)
            for (int k = 0; k < 3; ++k) sum[k] += val[3 * (size_t)list[i] + k];
        for (size_t i = 0; ok && i < n; ++i) {
            memcpy(acc + 3 * (size_t)list[i], sum, sizeof sum);
            had[list[i]] = 1;
        }
    }
    free(val), free(used), free(had), free(g.head), free(g.next), free(list);
    return ok;
}

/* mesh_assimp.c's walk multiplies by the node transform, the identity
 * here, as sums of products (rows 1, +0, +0; positions plus a +0
 * translation): a -0 position becomes +0, and a -0 normal component stays
 * -0 only when the other products are -0 too. Per-vertex outputs write
 * the sign (PLY, glTF bits; "-0" in CSV). */
static void as_walked(const double *v, double *o, int translate)
{
    for (int r = 0; r < 3; ++r) {
        double row[3] = {r == 0 ? 1.0 : 0.0, r == 1 ? 1.0 : 0.0, r == 2 ? 1.0 : 0.0};
        o[r] = row[0] * v[0] + row[1] * v[1] + row[2] * v[2];
        if (translate) o[r] += 0.0;
    }
}

/* mesh_assimp.c's walk: a unit normal in double, (0, 0, 1) when none. */
static void unit_or_z(const double *nrm, double *o)
{
    double n[3];
    as_walked(nrm, n, 0);
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (l > 1e-300 && isfinite(l)) {
        o[0] = n[0] / l, o[1] = n[1] / l, o[2] = n[2] / l;
    } else {
        o[0] = 0, o[1] = 0, o[2] = 1;
    }
}

/* All corners with a UV (normal), none, or -1 for a mix. */
static int corners_have(const native_mesh *m, int slot, size_t count)
{
    size_t with = 0;
    for (size_t k = 0; k < 3 * m->n_tri; ++k) {
        uint32_t i = m->corner[3 * k + slot];
        if (i == NONE) continue;
        if (i >= count) return -1;
        ++with;
    }
    return with == 0 ? 0 : with == 3 * m->n_tri ? 1 : -1;
}

static int fill(const native_mesh *m, const vertex_set *s, const double *acc, int has_uv, soak_mesh *o)
{
    o->positions = malloc(3 * s->n * sizeof(double));
    o->normals = malloc(3 * s->n * sizeof(double));
    o->uvs = has_uv ? malloc(2 * s->n * sizeof(double)) : NULL;
    o->indices = malloc(3 * m->n_tri * sizeof(unsigned));
    if (!o->positions || !o->normals || !o->indices || (has_uv && !o->uvs)) return 0;
    o->n_vertices = s->n;
    o->n_triangles = m->n_tri;
    for (size_t v = 0; v < s->n; ++v) {
        const uint32_t *key = s->vkey + 3 * v;
        double p[3];
        for (int k = 0; k < 3; ++k) p[k] = m->pos[3 * (size_t)key[0] + k];
        as_walked(p, o->positions + 3 * v, 1);
        if (has_uv)
            for (int k = 0; k < 2; ++k) o->uvs[2 * v + k] = m->uv[2 * (size_t)key[1] + k];
        double n[3];
        for (int k = 0; k < 3; ++k) n[k] = acc ? acc[3 * (size_t)key[0] + k] : m->nrm[3 * (size_t)key[2] + k];
        unit_or_z(n, o->normals + 3 * v);
    }
    for (size_t k = 0; k < 3 * m->n_tri; ++k) o->indices[k] = s->index ? s->index[k] : m->corner[3 * k];
    return 1;
}

/* PLY: the file's vertices as they are (corners name them directly). */
static void identity_set(const native_mesh *m, vertex_set *s)
{
    s->n = m->n_pos;
    s->index = NULL;
    s->vkey = malloc(3 * (m->n_pos + 1) * sizeof *s->vkey);
    for (size_t v = 0; s->vkey && v < m->n_pos; ++v)
        s->vkey[3 * v] = s->vkey[3 * v + 1] = s->vkey[3 * v + 2] = (uint32_t)v;
}

int native_finish(native_mesh *m, const soak_mesh_request *rq, soak_mesh *mesh, char *why, size_t whylen)
{
    int has_uv = corners_have(m, 1, m->n_uv), has_nrm = corners_have(m, 2, m->n_nrm);
    const char *no = m->n_tri == 0                       ? "no triangles"
                     : corners_have(m, 0, m->n_pos) != 1 ? "a corner without a position"
                     : has_uv < 0                        ? "some faces with UVs and some without"
                     : has_nrm < 0                       ? "some faces with normals and some without"
                     : rq->require_uvs && !has_uv        ? "no UVs"
                     : m->n_pos > 0xFFFFFFFEu            ? "too many vertices"
                                                         : NULL;
    for (size_t i = 0; !no && i < 3 * m->n_pos; ++i)
        if (!isfinite(m->pos[i])) no = "a non-finite coordinate";
    for (size_t i = 0; !no && has_uv && i < 2 * m->n_uv; ++i)
        if (!isfinite(m->uv[i])) no = "a non-finite texture coordinate";
    if (no) {
        snprintf(why, whylen, "%s", no);
        return 0;
    }
    native_encode_ngons(m);
    vertex_set s = {NULL, NULL, 0};
    double *acc = has_nrm ? NULL : calloc(3 * m->n_pos + 1, sizeof *acc);
    int ok = (has_nrm || acc) && (has_nrm || smooth_normals(m, acc));
    if (ok && m->indexed) identity_set(m, &s);
    else if (ok) ok = join_corners(m, &s);
    soak_mesh o = {0};
    ok = ok && s.vkey && fill(m, &s, acc, has_uv, &o);
    free(acc);
    free(s.vkey);
    free(s.index);
    if (!ok) {
        soak_mesh_free(&o);
        snprintf(why, whylen, "out of memory");
        return 0;
    }
    *mesh = o;
    return 1;
}
