/* The native reader's OBJ (mesh_native.h; Wavefront OBJ, Advanced
 * Visualizer manual, appendix B1): v (3 numbers, or 6 with a colour), vt
 * (2 or 3), vn (3) and f with 3 or 4 corners of positive indices, plus
 * lines that do not change the triangles (comments, s, mtllib, and o, g,
 * usemtl before the first face: Assimp splits a file into meshes at those,
 * which would reorder its triangles). Anything else declines the file. */
#include <stdio.h>
#include <string.h>

#include "mesh_native.h"

#define NONE UINT32_MAX

typedef struct obj_state {
    native_text t;
    native_mesh *m;
    size_t line;
    int faces_seen;
    char *why;
    size_t whylen;
} obj_state;

static int decline(obj_state *s, const char *what)
{
    snprintf(s->why, s->whylen, "OBJ line %zu: %s", s->line, what);
    return 0;
}

static int at_line_end(const native_text *t)
{
    return t->p >= t->end || *t->p == '\n' || (*t->p == '\r' && (t->p + 1 >= t->end || t->p[1] == '\n'));
}

/* Up to max numbers to the line's end into v: how many, or -1. A number
 * starting with '.' is declined: Assimp's component count (IsNumeric in
 * getNumComponentsInDataDefinition) does not count it, and then misreads
 * the line. */
static int numbers(native_text *t, float *v, int max)
{
    int n = 0;
    for (;;) {
        native_skip_blanks(t);
        if (at_line_end(t)) return n;
        if (n == max || *t->p == '.' || !native_parse_real(t, 0, &v[n])) return -1;
        ++n;
    }
}

static int add_floats(float **a, size_t *cap, size_t *n, size_t k, const float *v)
{
    if (!native_grow_floats(a, cap, *n, k)) return 0;
    memcpy(*a + k * *n, v, k * sizeof *v);
    ++*n;
    return 1;
}

static int vertex_line(obj_state *s, int kind)
{
    float v[6];
    native_mesh *m = s->m;
    int n = numbers(&s->t, v, 6);
    if (kind == 'p' && (n == 3 || n == 6))
        return add_floats(&m->pos, &m->cap_pos, &m->n_pos, 3, v) || decline(s, "out of memory");
    if (kind == 't' && (n == 2 || n == 3))
        return add_floats(&m->uv, &m->cap_uv, &m->n_uv, 2, v) || decline(s, "out of memory");
    if (kind == 'n' && n == 3) return add_floats(&m->nrm, &m->cap_nrm, &m->n_nrm, 3, v) || decline(s, "out of memory");
    return decline(s, "a vertex line of another shape (w, nan, a comma, ...)");
}

/* One index in [1, count] as a 0-based index. */
static int index_of(native_text *t, size_t count, uint32_t *out)
{
    uint32_t i;
    if (!native_parse_uint(t, &i) || i == 0 || i > count) return 0;
    *out = i - 1;
    return 1;
}

/* A corner v, v/vt, v//vn or v/vt/vn. */
static int corner(obj_state *s, uint32_t *c)
{
    native_text *t = &s->t;
    const native_mesh *m = s->m;
    c[1] = c[2] = NONE;
    if (!index_of(t, m->n_pos, &c[0])) return 0;
    if (t->p >= t->end || *t->p != '/') return 1;
    ++t->p;
    if (t->p < t->end && *t->p != '/' && !index_of(t, m->n_uv, &c[1])) return 0;
    if (t->p >= t->end || *t->p != '/') return 1;
    ++t->p;
    return index_of(t, m->n_nrm, &c[2]);
}

static int face_line(obj_state *s)
{
    uint32_t c[5 * 3];
    int n = 0;
    for (;;) {
        native_skip_blanks(&s->t);
        if (at_line_end(&s->t)) break;
        if (n == 5 || !corner(s, c + 3 * n)) return decline(s, "a face index that is not a vertex read so far");
        ++n;
        if (!at_line_end(&s->t) && *s->t.p != ' ' && *s->t.p != '\t') return decline(s, "a malformed corner");
    }
    if (n != 3 && n != 4) return decline(s, "a face of other than 3 or 4 corners");
    s->faces_seen = 1;
    return native_add_face(s->m, c, n) || decline(s, "a quad too close to flat at a corner to split as Assimp does");
}

static int word_is(const native_text *t, const char *w)
{
    size_t n = strlen(w);
    return (size_t)(t->end - t->p) > n && !memcmp(t->p, w, n) && (t->p[n] == ' ' || t->p[n] == '\t');
}

static void skip_line(native_text *t)
{
    const char *nl = memchr(t->p, '\n', (size_t)(t->end - t->p));
    t->p = nl ? nl + 1 : t->end;
}

static int one_line(obj_state *s)
{
    native_text *t = &s->t;
    native_skip_blanks(t);
    if (at_line_end(t) || *t->p == '#') return skip_line(t), 1;
    int ok;
    if (word_is(t, "v")) t->p += 1, ok = vertex_line(s, 'p');
    else if (word_is(t, "vt")) t->p += 2, ok = vertex_line(s, 't');
    else if (word_is(t, "vn")) t->p += 2, ok = vertex_line(s, 'n');
    else if (word_is(t, "f")) t->p += 1, ok = face_line(s);
    else if (word_is(t, "s") || word_is(t, "mtllib")) return skip_line(t), 1;
    else if ((word_is(t, "o") || word_is(t, "g") || word_is(t, "usemtl")) && !s->faces_seen) return skip_line(t), 1;
    else return decline(s, "a statement the native reader leaves to Assimp");
    if (ok) skip_line(t);
    return ok;
}

int native_read_obj(native_text t, native_mesh *m, char *why, size_t whylen)
{
    const unsigned char *b = (const unsigned char *)t.p;
    if ((b[0] == 0xFF && b[1] == 0xFE) || (b[0] == 0xFE && b[1] == 0xFF) || (b[0] == 0xEF && b[1] == 0xBB)) {
        snprintf(why, whylen, "OBJ with a byte-order mark");
        return 0;
    }
    if (memchr(t.p, '\\', (size_t)(t.end - t.p))) {
        snprintf(why, whylen, "OBJ with a backslash (line continuation)");
        return 0;
    }
    obj_state s = {t, m, 1, 0, why, whylen};
    for (; s.t.p < s.t.end; ++s.line)
        if (!one_line(&s)) return 0;
    return 1;
}
