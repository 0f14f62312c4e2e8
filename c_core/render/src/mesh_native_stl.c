/* The native reader's STL (mesh_native.h), binary and a strict ASCII
 * subset, giving what Assimp 5.2's STLLoader.cpp followed by its
 * JoinVerticesProcess.cpp gives: three corners per facet, each with the
 * facet's normal from the file (never recomputed, zero stays zero), then
 * corners joined into one vertex when their positions are equal (float
 * ==, so -0 meets +0) and their normals lie within 1e-5. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_native.h"

#define NONE UINT32_MAX

/* Positions hashed by value; slot[] holds the newest vertex at each
 * distinct position, older[v] the vertex before v at v's position. */
typedef struct stl_join {
    uint32_t *slot, *older;
    size_t mask, cap; /* cap: room in older */
} stl_join;

static uint32_t key_bits(float x)
{
    uint32_t b;
    x = x == 0 ? 0.0f : x; /* std::hash<float> gives -0 and +0 the same hash */
    memcpy(&b, &x, sizeof b);
    return b;
}

static size_t slot_of(const stl_join *j, const native_mesh *m, const float *p)
{
    uint64_t h = (uint64_t)key_bits(p[0]) * 0x9E3779B97F4A7C15ull ^ (uint64_t)key_bits(p[1]) * 0xC2B2AE3D27D4EB4Full ^
                 (uint64_t)key_bits(p[2]) * 0x165667B19E3779F9ull;
    size_t i = (size_t)(h ^ (h >> 29)) & j->mask;
    for (; j->slot[i] != NONE; i = (i + 1) & j->mask) {
        const float *q = m->pos + 3 * (size_t)j->slot[i];
        if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2]) break;
    }
    return i;
}

/* areVerticesEqual (JoinVerticesProcess.cpp, Assimp 5.2) on two normals:
 * the squared difference in float against 1e-5 squared. */
static int normals_join(const float *a, const float *b)
{
    const float eps = 1e-5f, eps2 = eps * eps;
    float x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return !(x * x + y * y + z * z > eps2);
}

/* The vertex of one corner. Assimp's unordered_map puts a new vertex at the
 * front of its bucket, so among the vertices at this position that match,
 * the newest is the one it finds. */
static int stl_corner(stl_join *j, native_mesh *m, const float *p, const float *n, uint32_t *c)
{
    size_t s = slot_of(j, m, p);
    for (uint32_t v = j->slot[s]; v != NONE; v = j->older[v])
        if (normals_join(m->nrm + 3 * (size_t)v, n)) {
            c[0] = c[2] = v, c[1] = NONE;
            return 1;
        }
    if (m->n_pos >= j->cap || m->n_pos >= 0xFFFFFFF0u || !native_grow_floats(&m->pos, &m->cap_pos, m->n_pos, 3) ||
        !native_grow_floats(&m->nrm, &m->cap_nrm, m->n_nrm, 3))
        return 0;
    uint32_t v = (uint32_t)m->n_pos++;
    m->n_nrm++;
    memcpy(m->pos + 3 * (size_t)v, p, 3 * sizeof *p);
    memcpy(m->nrm + 3 * (size_t)v, n, 3 * sizeof *n);
    j->older[v] = j->slot[s];
    j->slot[s] = v;
    c[0] = c[2] = v, c[1] = NONE;
    return 1;
}

static int stl_join_make(stl_join *j, size_t corners)
{
    size_t n = 1024;
    while (n < 2 * corners && n < ((size_t)1 << 40)) n *= 2;
    j->slot = malloc(n * sizeof *j->slot);
    j->older = malloc((corners + 1) * sizeof *j->older);
    j->mask = n - 1;
    j->cap = corners + 1;
    if (j->slot) memset(j->slot, 0xFF, n * sizeof *j->slot);
    return j->slot && j->older;
}

/* One facet: its normal and three positions, all finite (Assimp keeps a
 * NaN normal, which then joins any vertex at its position: left to it). */
static int stl_facet(stl_join *j, native_mesh *m, const float *nrm, const float pos[3][3], char *why, size_t whylen)
{
    for (int k = 0; k < 12; ++k)
        if (!isfinite(k < 3 ? nrm[k] : pos[(k - 3) / 3][(k - 3) % 3])) {
            snprintf(why, whylen, "a non-finite number in facet %zu", m->n_tri + 1);
            return 0;
        }
    uint32_t c[9];
    for (int k = 0; k < 3; ++k)
        if (!stl_corner(j, m, pos[k], nrm, c + 3 * k)) {
            snprintf(why, whylen, "out of memory");
            return 0;
        }
    if (!native_add_face(m, c, 3)) {
        snprintf(why, whylen, "out of memory");
        return 0;
    }
    return 1;
}

/* IsBinarySTL (STLLoader.cpp): the size is exactly 84 bytes plus 50 per
 * facet counted at byte 80, whatever the header says ("solid" too). Assimp
 * computes that size in 32 bits, so a huge count can wrap onto a small
 * file; it then refuses the file, and so is it declined here. */
static int stl_is_binary(native_text t, uint32_t *count)
{
    size_t size = (size_t)(t.end - t.p);
    if (size < 84) return 0;
    memcpy(count, t.p + 80, 4);
    return (uint64_t)(uint32_t)(84u + 50u * *count) == (uint64_t)size;
}

static int stl_read_binary(native_text t, uint32_t count, native_mesh *m, char *why, size_t whylen)
{
#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
    (void)t, (void)count, (void)m;
    snprintf(why, whylen, "binary STL on a big-endian host");
    return 0;
#else
    stl_join j = {NULL, NULL, 0, 0};
    int ok = stl_join_make(&j, 3 * (size_t)count);
    if (!ok) snprintf(why, whylen, "out of memory");
    const char *f = t.p + 84;
    for (uint32_t i = 0; ok && i < count; ++i, f += 50) {
        float nrm[3], pos[3][3];
        memcpy(nrm, f, sizeof nrm);
        memcpy(pos, f + 12, sizeof pos);
        ok = stl_facet(&j, m, nrm, pos, why, whylen);
    }
    free(j.slot);
    free(j.older);
    m->indexed = 1;
    return ok;
#endif
}

/* --- ASCII: solid NAME, facets of exactly "facet normal" three numbers,
 * "outer loop", three "vertex" lines, "endloop", "endfacet", then
 * "endsolid" and nothing after it. Several solids (Assimp makes a mesh of
 * each), a facet without its normal or with other than 3 vertices, words
 * Assimp skips and numbers it reads but parse_real does not are declined. */

static void skip_space_and_lines(native_text *t)
{
    while (t->p < t->end && (*t->p == ' ' || *t->p == '\t' || *t->p == '\r' || *t->p == '\n')) ++t->p;
}

/* The keyword w followed by a blank or a line end (the end of the file
 * too when last is set). */
static int word(native_text *t, const char *w, int last)
{
    size_t n = strlen(w);
    if ((size_t)(t->end - t->p) < n || memcmp(t->p, w, n)) return 0;
    const char *q = t->p + n;
    if (q == t->end ? !last : (*q != ' ' && *q != '\t' && *q != '\r' && *q != '\n')) return 0;
    t->p = q;
    return 1;
}

/* "KEY x y z" on one line, numbers after blanks only (Assimp's SkipSpaces
 * does not cross a line end), nothing else on the line. */
static int keyed_triple(native_text *t, const char *key, int own_line, float *v)
{
    if (own_line) skip_space_and_lines(t);
    else native_skip_blanks(t);
    if (!word(t, key, 0)) return 0;
    for (int k = 0; k < 3; ++k) {
        if (t->p < t->end && *t->p != ' ' && *t->p != '\t') return 0;
        native_skip_blanks(t);
        if (!native_parse_real(t, 0, v + k)) return 0;
    }
    native_skip_blanks(t);
    return t->p == t->end || *t->p == '\r' || *t->p == '\n';
}

static int lone_words(native_text *t, const char *a, const char *b)
{
    skip_space_and_lines(t);
    if (!word(t, a, 0)) return 0;
    if (!b) return 1;
    native_skip_blanks(t);
    return word(t, b, 0);
}

/* "solid" and at most one name word (Assimp takes the first word as the
 * name, under 1024 bytes, and reads the rest of the line as keywords). */
static int stl_solid_line(native_text *t)
{
    native_skip_blanks(t);
    if (!word(t, "solid", 0)) return 0;
    native_skip_blanks(t);
    const char *name = t->p;
    while (t->p < t->end && *t->p != ' ' && *t->p != '\t' && *t->p != '\r' && *t->p != '\n') ++t->p;
    native_skip_blanks(t);
    return t->p - name < 1000 && t->p < t->end && (*t->p == '\r' || *t->p == '\n');
}

static int stl_ascii_facets(native_text *t, stl_join *j, native_mesh *m, char *why, size_t whylen)
{
    for (;;) {
        skip_space_and_lines(t);
        if (word(t, "endsolid", 1)) break;
        float nrm[3], pos[3][3];
        int ok = lone_words(t, "facet", NULL) && keyed_triple(t, "normal", 0, nrm) && lone_words(t, "outer", "loop");
        for (int k = 0; ok && k < 3; ++k) ok = keyed_triple(t, "vertex", 1, pos[k]);
        if (!(ok && lone_words(t, "endloop", NULL) && lone_words(t, "endfacet", NULL))) {
            snprintf(why, whylen, "ASCII STL outside the plain facet layout near facet %zu", m->n_tri + 1);
            return 0;
        }
        if (!stl_facet(j, m, nrm, pos, why, whylen)) return 0;
    }
    while (t->p < t->end && *t->p != '\n') ++t->p;
    skip_space_and_lines(t);
    if (t->p != t->end) {
        snprintf(why, whylen, "ASCII STL with more than one solid or text after endsolid");
        return 0;
    }
    return 1;
}

static int stl_read_ascii(native_text t, native_mesh *m, char *why, size_t whylen)
{
    if (memchr(t.p, 0, (size_t)(t.end - t.p)) || !stl_solid_line(&t)) {
        snprintf(why, whylen, "neither binary STL (size against facet count) nor plain ASCII STL");
        return 0;
    }
    stl_join j = {NULL, NULL, 0, 0};
    int ok = stl_join_make(&j, (size_t)(t.end - t.p) / 24); /* a facet takes at least 86 bytes */
    if (!ok) snprintf(why, whylen, "out of memory");
    ok = ok && stl_ascii_facets(&t, &j, m, why, whylen);
    free(j.slot);
    free(j.older);
    m->indexed = 1;
    return ok;
}

int native_read_stl(native_text t, native_mesh *m, char *why, size_t whylen)
{
    uint32_t count = 0;
    if (stl_is_binary(t, &count)) {
        if (count == 0 || 84u + 50u * (uint64_t)count != (uint64_t)(t.end - t.p)) {
            snprintf(why, whylen, "binary STL without facets or with more than the file holds");
            return 0;
        }
        return stl_read_binary(t, count, m, why, whylen);
    }
    return stl_read_ascii(t, m, why, whylen);
}
