/* Nearest-surface analysis at commit (soak/geometry.h): which spheres no
 * other surface enters (isolated, so a walk inside needs no scene
 * traversal) and the clear ball of every triangle object. */
#include <stdbool.h>
#include <stdlib.h>

#include "geometry_internal.h"

/* Closest point to p on triangle abc, by the Voronoi regions of its
 * vertices, edges and face (C. Ericson, Real-Time Collision Detection, 2005,
 * sec. 5.1.5). */
static soak_vec3 closest_on_triangle(soak_vec3 p, soak_vec3 a, soak_vec3 b, soak_vec3 c)
{
    soak_vec3 ab = soak_v3_sub(b, a), ac = soak_v3_sub(c, a), ap = soak_v3_sub(p, a);
    double d1 = soak_v3_dot(ab, ap), d2 = soak_v3_dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    soak_vec3 bp = soak_v3_sub(p, b);
    double d3 = soak_v3_dot(ab, bp), d4 = soak_v3_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return soak_v3_add(a, soak_v3_scale(ab, d1 / (d1 - d3)));
    soak_vec3 cp = soak_v3_sub(p, c);
    double d5 = soak_v3_dot(ab, cp), d6 = soak_v3_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return soak_v3_add(a, soak_v3_scale(ac, d2 / (d2 - d6)));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return soak_v3_add(b, soak_v3_scale(soak_v3_sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
    double den = va + vb + vc;
    if (!(fabs(den) > 0)) return a; /* degenerate triangle */
    return soak_v3_add(a, soak_v3_add(soak_v3_scale(ab, vb / den), soak_v3_scale(ac, vc / den)));
}

typedef struct nearest_query {
    const soak_geometry *g;
    unsigned skip; /* object not counted */
    int skip_concentric; /* nor any sphere centred exactly at p */
    soak_vec3 p;
    double best;   /* smallest distance found so far, double */
} nearest_query;

/* rtcPointQuery callback, once per primitive whose bounds meet the query
 * ball: exact distance in double, and the ball shrinks to it. */
static bool nearest_prim(struct RTCPointQueryFunctionArguments *args)
{
    nearest_query *q = args->userPtr;
    if (args->geomID >= q->g->count || args->geomID == q->skip) return false;
    const geo_object *o = &q->g->objects[args->geomID];
    if (q->skip_concentric && o->kind == SOAK_SHAPE_SPHERE && o->center.x == q->p.x && o->center.y == q->p.y &&
        o->center.z == q->p.z)
        return false;
    double d;
    if (o->kind == SOAK_SHAPE_SPHERE) {
        d = fabs(soak_v3_len(soak_v3_sub(q->p, o->center)) - o->radius);
    } else {
        const unsigned *tri = o->idx + 3 * args->primID;
        d = soak_v3_len(soak_v3_sub(q->p, closest_on_triangle(q->p, vtx(o->pos, tri[0]), vtx(o->pos, tri[1]), vtx(o->pos, tri[2]))));
    }
    if (!(d < q->best)) return false;
    q->best = d;
    args->query->radius = nextafterf((float)d, INFINITY); /* rounded up: never culls a nearer primitive */
    return true;
}

/* A sphere is isolated when every other surface is at least its radius from
 * its centre (less a relative 1e-9, so a plane it rests on, touching it at
 * one point, does not count). */
/* Distance from c to the nearest surface within reach of radius r, other
 * than object skip (and, with skip_concentric, any sphere centred at c). */
static double nearest_surface(const soak_geometry *g, unsigned skip, int skip_concentric, soak_vec3 c, double r)
{
    nearest_query q = {g, skip, skip_concentric, c, INFINITY};
    float reach = (float)(r * (1 + 1e-6)) + 1e-6f * (float)(1 + soak_v3_len(c));
    struct RTCPointQuery pq = {(float)c.x, (float)c.y, (float)c.z, 0.0f, reach};
    struct RTCPointQueryContext ctx;
    rtcInitPointQueryContext(&ctx);
    rtcPointQuery(g->scene, &pq, &ctx, nearest_prim, &q);
    return q.best;
}

static int sphere_isolated(const soak_geometry *g, unsigned id)
{
    const geo_object *o = &g->objects[id];
    return nearest_surface(g, id, 0, o->center, o->radius) >= o->radius * (1 - 1e-9);
}

static int by_centre(const void *pa, const void *pb)
{
    const geo_object *a = *(const geo_object *const *)pa, *b = *(const geo_object *const *)pb;
    if (a->center.x != b->center.x) return a->center.x < b->center.x ? -1 : 1;
    if (a->center.y != b->center.y) return a->center.y < b->center.y ? -1 : 1;
    if (a->center.z != b->center.z) return a->center.z < b->center.z ? -1 : 1;
    return a->radius < b->radius ? -1 : a->radius > b->radius;
}

/* Spheres sharing one centre (sorted by radius in s[0..k)): one point query
 * for the surfaces outside the group instead of k queries that each visit
 * all k (quadratic for stacked spheres). Inside the group the nearest other
 * surface from the centre is the smallest other radius. */
static void concentric_isolated(const soak_geometry *g, geo_object **s, size_t k)
{
    double outside = nearest_surface(g, (unsigned)-1, 1, s[0]->center, s[k - 1]->radius);
    for (size_t i = 0; i < k; ++i) {
        double inside = s[i == 0 ? 1 : 0]->radius;
        double d = inside < outside ? inside : outside;
        s[i]->isolated = d >= s[i]->radius * (1 - 1e-9);
    }
}

/* Sets isolated on every sphere; SOAK_ERR_NOMEM when the sort has no memory. */
soak_status geo_mark_isolated(soak_geometry *g)
{
    size_t n = 0;
    for (unsigned i = 0; i < g->count; ++i) n += g->objects[i].kind == SOAK_SHAPE_SPHERE;
    if (n == 0) return SOAK_OK;
    geo_object **s = malloc(n * sizeof *s);
    if (!s) return SOAK_ERR_NOMEM;
    n = 0;
    for (unsigned i = 0; i < g->count; ++i)
        if (g->objects[i].kind == SOAK_SHAPE_SPHERE) s[n++] = &g->objects[i];
    qsort(s, n, sizeof *s, by_centre);
    for (size_t i = 0; i < n;) {
        size_t k = 1;
        while (i + k < n && s[i + k]->center.x == s[i]->center.x && s[i + k]->center.y == s[i]->center.y &&
               s[i + k]->center.z == s[i]->center.z)
            ++k;
        if (k == 1) s[i]->isolated = sphere_isolated(g, (unsigned)(s[i] - g->objects));
        else concentric_isolated(g, s + i, k);
        i += k;
    }
    free(s);
    return SOAK_OK;
}

/* The clear ball of a triangle object: around the centre of its bounds, up
 * to the nearest surface of any object, less a margin above Embree's float
 * error (the scale of soak_geometry_offset's), so a segment inside it meets
 * no surface for Embree either. A closed convex object's ball is its
 * inscribed sphere about that centre; a flat or hollow one gets none. */
void geo_mark_clear_ball(soak_geometry *g, unsigned id)
{
    geo_object *o = &g->objects[id];
    soak_vec3 lo, hi;
    o->clear_r2 = 0;
    if (soak_geometry_object_bounds(g, id, &lo, &hi) != SOAK_OK) return;
    soak_vec3 c = soak_v3_scale(soak_v3_add(lo, hi), 0.5);
    double reach = 0.5 * soak_v3_len(soak_v3_sub(hi, lo));
    double m = fmax(fmax(fabs(c.x), fabs(c.y)), fabs(c.z)) + reach;
    double r = fmin(nearest_surface(g, (unsigned)-1, 0, c, reach), reach) * (1 - 1e-6) - 1e-5 * (1 + m);
    o->clear_c = c;
    o->clear_r2 = r > 0 ? r * r : 0;
}
