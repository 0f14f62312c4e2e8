/* The native reader's PLY (mesh_native.h; Turk, "The PLY polygon file
 * format", 1994): ASCII, binary little- and big-endian; an element vertex
 * whose x, y, z (and nx, ny, nz, and u/s/tx/texture_u with
 * v/t/ty/texture_v, Assimp 5.2's names) are float or double, followed by an
 * element face with one list vertex_indices (or vertex_index) of 3 or 4
 * corners; other scalar properties are skipped. Anything else (other
 * elements or lists, per-face texcoord, tristrips, integer coordinates)
 * declines the file. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_native.h"

#define NONE UINT32_MAX
#define MAX_PROPS 32

enum { PLY_ASCII, PLY_LE, PLY_BE };
enum { S_X, S_Y, S_Z, S_NX, S_NY, S_NZ, S_U, S_V, S_COUNT };

typedef struct ply_prop {
    int type, list_type, is_list, sem; /* type: byte size, negative for signed, 5 float, 9 double; sem or -1 */
} ply_prop;

typedef struct ply_element {
    size_t count;
    int n;
    ply_prop prop[MAX_PROPS];
} ply_element;

typedef struct ply_file {
    int format;
    ply_element vertex, face;
    int have_face;
    int sem_at[S_COUNT]; /* the vertex property of each semantic, or -1 */
    char *why;
    size_t whylen;
} ply_file;

static int decline(ply_file *f, const char *what)
{
    snprintf(f->why, f->whylen, "PLY: %s", what);
    return 0;
}

static int type_of(const char *w)
{
    static const struct {
        const char *name;
        int type;
    } types[] = {{"char", -1},  {"int8", -1},   {"uchar", 1},  {"uint8", 1},   {"short", -2},  {"int16", -2},
                 {"ushort", 2}, {"uint16", 2},  {"int", -4},   {"int32", -4},  {"uint", 4},    {"uint32", 4},
                 {"float", 5},  {"float32", 5}, {"double", 9}, {"float64", 9}, {"double64", 9}};
    for (size_t i = 0; i < sizeof types / sizeof *types; ++i)
        if (!strcmp(w, types[i].name)) return types[i].type;
    return 0;
}

static int size_of(int type) { return type == 5 ? 4 : type == 9 ? 8 : abs(type); }

static int semantic_of(const char *w)
{
    static const char *const names[][4] = {
        {"x"}, {"y"}, {"z"}, {"nx"}, {"ny"}, {"nz"}, {"u", "s", "tx", "texture_u"}, {"v", "t", "ty", "texture_v"}};
    for (int s = 0; s < S_COUNT; ++s)
        for (int k = 0; k < 4 && names[s][k]; ++k)
            if (!strcmp(w, names[s][k])) return s;
    return -1;
}

/* The next header line's words (at most 6); 0 at the end of the file. */
static int header_words(native_text *t, char w[6][32], int *n)
{
    const char *nl = memchr(t->p, '\n', (size_t)(t->end - t->p));
    if (!nl || nl - t->p > 1000) return 0;
    *n = 0;
    for (const char *p = t->p; p < nl;) {
        while (p < nl && *p == ' ') ++p;
        const char *q = p;
        while (q < nl && *q != ' ') ++q;
        if (q == p) break;
        if (*n == 6 || q - p >= 32) return 0;
        memcpy(w[*n], p, (size_t)(q - p));
        w[(*n)++][q - p] = '\0';
        p = q;
    }
    t->p = nl + 1;
    return 1;
}

static int add_property(ply_file *f, ply_element *e, char w[6][32], int n)
{
    if (e->n == MAX_PROPS) return decline(f, "too many properties");
    ply_prop *p = &e->prop[e->n];
    p->is_list = n == 5 && !strcmp(w[1], "list");
    p->list_type = p->is_list ? type_of(w[2]) : 0;
    p->type = type_of(w[p->is_list ? 3 : 1]);
    p->sem = -1;
    if ((n != 3 && !p->is_list) || !p->type || (p->is_list && (!p->list_type || p->list_type > 4)))
        return decline(f, "a property line the native reader does not take");
    const char *name = w[n - 1];
    if (e == &f->face) {
        int is_index = !strcmp(name, "vertex_indices") || !strcmp(name, "vertex_index");
        if (p->is_list != is_index || (is_index && p->type > 4))
            return decline(f, "a face property other than scalars and vertex_indices");
        p->sem = is_index ? 0 : -1;
    } else {
        p->sem = semantic_of(name);
        if (p->is_list) return decline(f, "a list in the vertices");
        if (p->sem >= 0 && (p->type < 5 || f->sem_at[p->sem] >= 0))
            return decline(f, "an integer or repeated coordinate");
        if (p->sem >= 0) f->sem_at[p->sem] = e->n;
    }
    e->n++;
    return 1;
}

static int element_line(ply_file *f, char w[6][32], int n, ply_element **cur)
{
    char *end = NULL;
    unsigned long long count = n == 3 ? strtoull(w[2], &end, 10) : 0;
    if (n != 3 || !end || *end || w[2][0] == '-' || count > 0xFFFFFFFEull)
        return decline(f, "a malformed element line");
    if (!strcmp(w[1], "vertex") && !*cur) *cur = &f->vertex;
    else if (!strcmp(w[1], "face") && *cur == &f->vertex) *cur = &f->face, f->have_face = 1;
    else return decline(f, "elements other than vertex then face");
    (*cur)->count = (size_t)count;
    return 1;
}

static int header(native_text *t, ply_file *f)
{
    char w[6][32];
    int n;
    ply_element *cur = NULL;
    if (!header_words(t, w, &n) || n != 1 || strcmp(w[0], "ply")) return decline(f, "no ply line");
    if (!header_words(t, w, &n) || n != 3 || strcmp(w[0], "format") || strcmp(w[2], "1.0"))
        return decline(f, "no format line");
    f->format = !strcmp(w[1], "ascii")                  ? PLY_ASCII
                : !strcmp(w[1], "binary_little_endian") ? PLY_LE
                : !strcmp(w[1], "binary_big_endian")    ? PLY_BE
                                                        : -1;
    if (f->format < 0) return decline(f, "an unknown format");
    for (;;) {
        size_t left = (size_t)(t->end - t->p);
        if ((left >= 7 && !memcmp(t->p, "comment", 7)) || (left >= 8 && !memcmp(t->p, "obj_info", 8))) {
            const char *nl = memchr(t->p, '\n', (size_t)(t->end - t->p));
            if (!nl) return decline(f, "no end_header");
            t->p = nl + 1;
            continue;
        }
        if (!header_words(t, w, &n) || n == 0) return decline(f, "a malformed header");
        if (!strcmp(w[0], "end_header") && n == 1) break;
        if (!strcmp(w[0], "element") && !element_line(f, w, n, &cur)) return 0;
        if (!strcmp(w[0], "property") && (!cur || !add_property(f, cur, w, n)))
            return cur ? 0 : decline(f, "a property before any element");
        if (strcmp(w[0], "element") && strcmp(w[0], "property")) return decline(f, "an unknown header line");
    }
    if (!f->have_face || f->face.n == 0 || f->sem_at[S_X] < 0 || f->sem_at[S_Y] < 0 || f->sem_at[S_Z] < 0)
        return decline(f, "no faces or no x, y, z");
    int nn = (f->sem_at[S_NX] >= 0) + (f->sem_at[S_NY] >= 0) + (f->sem_at[S_NZ] >= 0);
    int nuv = (f->sem_at[S_U] >= 0) + (f->sem_at[S_V] >= 0);
    int lists = 0;
    for (int i = 0; i < f->face.n; ++i) lists += f->face.prop[i].is_list;
    if ((nn != 0 && nn != 3) || nuv == 1 || lists != 1)
        return decline(f, "partial normals or UVs, or no vertex_indices");
    return 1;
}

/* --- binary values --- */

static double binary_value(const unsigned char *b, int type, int big)
{
    unsigned char c[8];
    int n = size_of(type);
    for (int i = 0; i < n; ++i) c[i] = big ? b[n - 1 - i] : b[i];
    if (type == 5) {
        float x;
        memcpy(&x, c, 4);
        return x;
    }
    if (type == 9) {
        double x;
        memcpy(&x, c, 8);
        return x;
    }
    unsigned long long u = 0;
    for (int i = n - 1; i >= 0; --i) u = u << 8 | c[i];
    if (type < 0 && (u >> (8 * n - 1))) return (double)(long long)(u | (~0ull << (8 * n - 1) << 1));
    return (double)u;
}

static int alloc_vertices(native_mesh *m, const ply_file *f)
{
    size_t n = f->vertex.count + 1;
    m->pos = malloc(3 * n * sizeof *m->pos);
    m->uv = f->sem_at[S_U] >= 0 ? malloc(2 * n * sizeof *m->uv) : NULL;
    m->nrm = f->sem_at[S_NX] >= 0 ? malloc(3 * n * sizeof *m->nrm) : NULL;
    m->n_pos = f->vertex.count;
    m->n_uv = m->uv ? m->n_pos : 0;
    m->n_nrm = m->nrm ? m->n_pos : 0;
    m->indexed = 1;
    return m->pos && (m->uv || f->sem_at[S_U] < 0) && (m->nrm || f->sem_at[S_NX] < 0);
}

static void store(native_mesh *m, size_t v, int sem, float x)
{
    if (sem <= S_Z) m->pos[3 * v + (size_t)sem] = x;
    else if (sem <= S_NZ) m->nrm[3 * v + (size_t)(sem - S_NX)] = x;
    else m->uv[2 * v + (size_t)(sem - S_U)] = x;
}

/* Bytes of a vertex in a binary file (each value at least 2 bytes in an
 * ASCII one: a digit and a blank). */
static size_t vertex_bytes(const ply_file *f)
{
    size_t rec = 0;
    for (int i = 0; i < f->vertex.n; ++i) rec += f->format == PLY_ASCII ? 2 : (size_t)size_of(f->vertex.prop[i].type);
    return rec ? rec : 1;
}

static int binary_vertices(native_text *t, const ply_file *f, native_mesh *m)
{
    const unsigned char *b = (const unsigned char *)t->p;
    for (size_t v = 0; v < f->vertex.count; ++v)
        for (int i = 0; i < f->vertex.n; ++i) {
            const ply_prop *p = &f->vertex.prop[i];
            if (p->sem >= 0) store(m, v, p->sem, (float)binary_value(b, p->type, f->format == PLY_BE));
            b += size_of(p->type);
        }
    t->p = (const char *)b;
    return 1;
}

/* One face's corners (count 3 or 4) into c as (v, uv, normal) triples. */
static int corners(native_mesh *m, const double *idx, int count, uint32_t *c)
{
    if (count != 3 && count != 4) return 0;
    for (int k = 0; k < count; ++k) {
        if (!(idx[k] >= 0 && idx[k] < (double)m->n_pos)) return 0;
        uint32_t v = (uint32_t)idx[k];
        c[3 * k] = v, c[3 * k + 1] = m->uv ? v : NONE, c[3 * k + 2] = m->nrm ? v : NONE;
    }
    return native_add_face(m, c, count);
}

static int binary_faces(native_text *t, const ply_file *f, native_mesh *m)
{
    const unsigned char *b = (const unsigned char *)t->p, *end = (const unsigned char *)t->end;
    int big = f->format == PLY_BE;
    for (size_t k = 0; k < f->face.count; ++k) {
        double idx[4];
        int count = 0;
        for (int i = 0; i < f->face.n; ++i) {
            const ply_prop *p = &f->face.prop[i];
            if (!p->is_list) {
                if (end - b < size_of(p->type)) return 0;
                b += size_of(p->type);
                continue;
            }
            if (end - b < size_of(p->list_type)) return 0;
            double n = binary_value(b, p->list_type, big);
            b += size_of(p->list_type);
            if (!(n >= 3 && n <= 4) || end - b < (long)n * size_of(p->type)) return 0;
            count = (int)n;
            for (int j = 0; j < count; ++j, b += size_of(p->type)) idx[j] = binary_value(b, p->type, big);
        }
        uint32_t c[12];
        if (!corners(m, idx, count, c)) return 0;
    }
    t->p = (const char *)b;
    return 1;
}

/* --- ASCII values: one element per line, values between blanks --- */

static int ascii_value(native_text *t, int type, double *out)
{
    native_skip_blanks(t);
    if (type >= 5) {
        float x;
        if (!native_parse_real(t, type == 9, &x)) return 0;
        *out = x;
        return 1;
    }
    int neg = t->p < t->end && *t->p == '-';
    uint32_t u;
    if (neg) ++t->p;
    if (!native_parse_uint(t, &u)) return 0;
    *out = neg ? -(double)u : (double)u;
    return 1;
}

static int ascii_line_end(native_text *t)
{
    native_skip_blanks(t);
    if (t->p < t->end && *t->p == '\r') ++t->p;
    if (t->p < t->end && *t->p != '\n') return 0;
    if (t->p < t->end) ++t->p;
    return 1;
}

static int ascii_vertices(native_text *t, const ply_file *f, native_mesh *m)
{
    for (size_t v = 0; v < f->vertex.count; ++v) {
        for (int i = 0; i < f->vertex.n; ++i) {
            const ply_prop *p = &f->vertex.prop[i];
            double x;
            if (!ascii_value(t, p->type, &x)) return 0;
            if (p->sem >= 0) store(m, v, p->sem, (float)x);
        }
        if (!ascii_line_end(t)) return 0;
    }
    return 1;
}

static int ascii_faces(native_text *t, const ply_file *f, native_mesh *m)
{
    if (f->face.count > (size_t)(t->end - t->p) / 2) return 0;
    for (size_t k = 0; k < f->face.count; ++k) {
        double idx[4], n = 0;
        int count = 0;
        for (int i = 0; i < f->face.n; ++i) {
            const ply_prop *p = &f->face.prop[i];
            if (!ascii_value(t, p->is_list ? p->list_type : p->type, &n)) return 0;
            if (!p->is_list) continue;
            if (!(n >= 3 && n <= 4)) return 0;
            count = (int)n;
            for (int j = 0; j < count; ++j)
                if (!ascii_value(t, p->type, &idx[j])) return 0;
        }
        uint32_t c[12];
        if (!ascii_line_end(t) || !corners(m, idx, count, c)) return 0;
    }
    return 1;
}

int native_read_ply(native_text t, native_mesh *m, char *why, size_t whylen)
{
    ply_file f;
    memset(&f, 0, sizeof f);
    for (int s = 0; s < S_COUNT; ++s) f.sem_at[s] = -1;
    f.why = why, f.whylen = whylen;
    if (!header(&t, &f)) return 0;
    if (f.vertex.count > (size_t)(t.end - t.p) / vertex_bytes(&f))
        return decline(&f, "more vertices than the file holds");
    if (!alloc_vertices(m, &f)) return decline(&f, "out of memory");
    int ascii = f.format == PLY_ASCII;
    if (!(ascii ? ascii_vertices(&t, &f, m) : binary_vertices(&t, &f, m)))
        return decline(&f, "vertices that are short, malformed or more than the file holds");
    if (!(ascii ? ascii_faces(&t, &f, m) : binary_faces(&t, &f, m)))
        return decline(&f, "faces that are short, malformed, of other than 3 or 4 corners, or name missing vertices");
    return 1;
}
