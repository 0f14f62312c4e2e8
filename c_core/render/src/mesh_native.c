/* The native reader's number parser and its face splitting, shared by the
 * formats (mesh_native.h). The entry is mesh_native_read.c; the vertices,
 * normals and the final soak_mesh are made by mesh_native_finish.c; the
 * formats by mesh_native_obj.c and mesh_native_ply.c. */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_import.h"
#include "mesh_native.h"

/* The table fast_atof.h multiplies the decimals by: 10^-k as the double
 * nearest each decimal literal. */
static const double decimal_scale[16] = {0.0,  0.1,  0.01,  1e-3,  1e-4,  1e-5,  1e-6,  1e-7,
                                         1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15};
#define MAX_DECIMALS 15

void native_mesh_free(native_mesh *m)
{
    free(m->pos);
    free(m->uv);
    free(m->nrm);
    free(m->corner);
    free(m->kind);
    memset(m, 0, sizeof *m);
}

int native_grow_floats(float **a, size_t *cap, size_t used, size_t k)
{
    if ((used + 1) * k <= *cap) return 1;
    size_t want = *cap ? 2 * *cap : 1024 * k;
    float *b = realloc(*a, want * sizeof *b);
    if (!b) return 0;
    *a = b;
    *cap = want;
    return 1;
}

static int is_digit(char c) { return c >= '0' && c <= '9'; }

void native_skip_blanks(native_text *t)
{
    while (t->p < t->end && (*t->p == ' ' || *t->p == '\t')) ++t->p;
}

/* Digits at p as an integer (at most max of them; the rest skipped): the
 * count read in *n; 0 when there is none or more than 18 to read. */
static int digits(const char **p, const char *end, int max, unsigned long long *v, int *n)
{
    const char *q = *p;
    unsigned long long x = 0;
    int k = 0;
    for (; q < end && is_digit(*q); ++q) {
        if (k == max) continue;
        x = 10 * x + (unsigned long long)(*q - '0');
        ++k;
    }
    if (q == *p || (max > MAX_DECIMALS && q - *p > 18)) return 0;
    *p = q, *v = x, *n = k;
    return 1;
}

int native_parse_real(native_text *t, int as_double, float *out)
{
    const char *p = t->p, *end = t->end;
    int neg = p < end && *p == '-';
    if (p < end && (*p == '-' || *p == '+')) ++p;
    unsigned long long ip = 0, fp = 0, ep = 0;
    int n = 0, nf = 0, ne = 0;
    int lead = p < end && is_digit(*p), frac = p + 1 < end && *p == '.' && is_digit(p[1]);
    if (!lead && !frac) return 0;
    if (lead && !digits(&p, end, 64, &ip, &n)) return 0;
    frac = p + 1 < end && *p == '.' && is_digit(p[1]);
    if (frac) {
        ++p;
        digits(&p, end, MAX_DECIMALS, &fp, &nf);
    } else if (p < end && *p == '.') {
        ++p;
    }
    int eneg = 0;
    if (p < end && (*p == 'e' || *p == 'E')) {
        ++p;
        eneg = p < end && *p == '-';
        if (p < end && (*p == '-' || *p == '+')) ++p;
        if (!digits(&p, end, 64, &ep, &ne)) return 0;
    }
    if (p < end && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') return 0; /* "1,5", "1x" */
    /* The same operations in the same precision as fast_atoreal_move. */
    if (as_double) {
        double f = (double)ip;
        if (frac) f += (double)fp * decimal_scale[nf];
        if (ne) f *= pow(10.0, eneg ? -(double)ep : (double)ep);
        *out = (float)(neg ? -f : f);
    } else {
        float f = (float)ip;
        if (frac) f += (float)((double)fp * decimal_scale[nf]);
        if (ne) f *= powf(10.0f, eneg ? -(float)ep : (float)ep);
        *out = neg ? -f : f;
    }
    t->p = p;
    return 1;
}

int native_parse_uint(native_text *t, uint32_t *out)
{
    const char *p = t->p;
    unsigned long long v = 0;
    for (; p < t->end && is_digit(*p) && v <= 0xFFFFFFFFull; ++p) v = 10 * v + (unsigned long long)(*p - '0');
    if (p == t->p || v > 0xFFFFFFFFull) return 0;
    t->p = p;
    *out = (uint32_t)v;
    return 1;
}

static int push_triangle(native_mesh *m, const uint32_t *a, const uint32_t *b, const uint32_t *c, int kind)
{
    if (m->n_tri == m->cap_tri) {
        size_t want = m->cap_tri ? 2 * m->cap_tri : 4096;
        uint32_t *g = realloc(m->corner, want * 9 * sizeof *g);
        if (g) m->corner = g;
        unsigned char *k = g ? realloc(m->kind, want) : NULL;
        if (!k) return 0;
        m->kind = k;
        m->cap_tri = want;
    }
    uint32_t *o = m->corner + 9 * m->n_tri;
    memcpy(o, a, 3 * sizeof *o);
    memcpy(o + 3, b, 3 * sizeof *o);
    memcpy(o + 6, c, 3 * sizeof *o);
    m->kind[m->n_tri++] = (unsigned char)kind;
    return 1;
}

static double unit_diff(const float *a, const float *b, double *u)
{
    double l = 0;
    for (int k = 0; k < 3; ++k) u[k] = (double)a[k] - (double)b[k], l += u[k] * u[k];
    l = sqrt(l);
    for (int k = 0; k < 3 && l > 0; ++k) u[k] /= l;
    return l;
}

/* Assimp's quad rule (TriangulateProcess.cpp, 5.2): fan from the first
 * corner whose two angles to the opposite diagonal add up to more than pi
 * (the concave one), else from corner 0. -1 when a corner is within 1e-4
 * rad of that test's threshold or an edge is degenerate: the float
 * arithmetic there could decide either way. */
static int quad_start(const native_mesh *m, const uint32_t *c)
{
    const float *P[4];
    for (int i = 0; i < 4; ++i) {
        if (c[3 * i] >= m->n_pos) return -1;
        P[i] = m->pos + 3 * (size_t)c[3 * i];
    }
    for (int i = 0; i < 4; ++i) {
        double l[3], d[3], r[3];
        double ll = unit_diff(P[(i + 3) % 4], P[i], l), ld = unit_diff(P[(i + 2) % 4], P[i], d);
        double lr = unit_diff(P[(i + 1) % 4], P[i], r);
        if (!(ll > 1e-20 && ld > 1e-20 && lr > 1e-20)) return -1;
        double a = acos(fmin(1.0, fmax(-1.0, l[0] * d[0] + l[1] * d[1] + l[2] * d[2]))) +
                   acos(fmin(1.0, fmax(-1.0, r[0] * d[0] + r[1] * d[1] + r[2] * d[2])));
        if (!(fabs(a - M_PI) > 1e-4)) return -1;
        if (a > M_PI) return i;
    }
    return 0;
}

int native_add_face(native_mesh *m, const uint32_t *c, int count)
{
    if (count == 3) return push_triangle(m, c, c + 3, c + 6, 0);
    int s = quad_start(m, c);
    if (s < 0) return 0;
    m->any_quad = 1;
    const uint32_t *q0 = c + 3 * s, *q1 = c + 3 * ((s + 1) % 4), *q2 = c + 3 * ((s + 2) % 4),
                   *q3 = c + 3 * ((s + 3) % 4);
    return push_triangle(m, q0, q1, q2, 1) && push_triangle(m, q0, q2, q3, 2);
}

/* Corners (a, b, c) to (c, a, b) (right) or (b, c, a) (left). */
static void rotate(uint32_t *t, int right)
{
    uint32_t tmp[9];
    memcpy(tmp, t, sizeof tmp);
    memcpy(t, right ? tmp + 6 : tmp + 3, 3 * sizeof *t);
    memcpy(t + 3, right ? tmp : tmp + 6, 3 * sizeof *t);
    memcpy(t + 6, right ? tmp + 3 : tmp, 3 * sizeof *t);
}

/* Assimp's n-gon encoding (TriangulateProcess.cpp, 5.2; only in a mesh
 * it triangulates) rotates a face's corners when its first vertex is the
 * previous face's first, so that the two do not read as one polygon: the
 * same triangles, other first corners. Only shared vertices can repeat
 * (Assimp's OBJ corners are never shared). */
void native_encode_ngons(native_mesh *m)
{
    if (!m->indexed || !m->any_quad) return;
    uint32_t last = UINT32_MAX;
    for (size_t t = 0; t < m->n_tri; ++t) {
        uint32_t *c = m->corner + 9 * t;
        if (c[0] == last) {
            rotate(c, 1);
            if (m->kind[t] == 1 && t + 1 < m->n_tri) rotate(c + 9, 0);
        }
        last = c[0];
        t += m->kind[t] == 1;
    }
}
