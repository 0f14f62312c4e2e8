/* The clear box of a box object (soak/geometry.h, soak_geometry_clear_distance):
 * its interior, less a margin above Embree's float error (the scale of
 * soak_geometry_offset's, as for the clear ball), when no other object's
 * bounds meet it. A box is convex, so a segment with both ends in it meets
 * no surface, and the distance from a point in it to the nearest face is
 * the smallest of six coordinate differences. The inscribed ball of a thin
 * sheet covers only its middle; a walk in the sheet spent a fifth of its
 * work on occlusion rays that this answers without traversal. For the same
 * reason a ray from inside such a box leaves it through the nearest of the
 * three faces ahead before meeting any other surface: the walk's boundary
 * and exit queries are answered in closed form (geo_box_exit). */
#include "geometry_internal.h"

static int bounds_meet(soak_vec3 alo, soak_vec3 ahi, soak_vec3 blo, soak_vec3 bhi)
{
    return alo.x <= bhi.x && blo.x <= ahi.x && alo.y <= bhi.y && blo.y <= ahi.y && alo.z <= bhi.z && blo.z <= ahi.z;
}

void geo_mark_clear_box(soak_geometry *g, unsigned id)
{
    geo_object *o = &g->objects[id];
    o->has_clear_box = 0;
    soak_vec3 lo, hi, olo, ohi;
    if (o->kind != SOAK_SHAPE_BOX || soak_geometry_object_bounds(g, id, &lo, &hi) != SOAK_OK) return;
    for (unsigned i = 0; i < g->count; ++i) {
        if (i == id) continue;
        if (soak_geometry_object_bounds(g, i, &olo, &ohi) != SOAK_OK || bounds_meet(lo, hi, olo, ohi)) return;
    }
    double m = fmax(fmax(fmax(fabs(lo.x), fabs(hi.x)), fmax(fabs(lo.y), fabs(hi.y))), fmax(fabs(lo.z), fabs(hi.z)));
    double margin = 1e-5 * (1 + m);
    soak_vec3 e = soak_v3(margin, margin, margin);
    o->clear_lo = soak_v3_add(lo, e);
    o->clear_hi = soak_v3_sub(hi, e);
    o->has_clear_box = o->clear_lo.x < o->clear_hi.x && o->clear_lo.y < o->clear_hi.y && o->clear_lo.z < o->clear_hi.z;
    o->box_lo = lo;
    o->box_hi = hi;
}

int geo_box_exit(const geo_object *o, unsigned object_id, const soak_ray *ray, soak_hit *hit, int *found)
{
    soak_vec3 p0 = soak_v3_add(ray->org, soak_v3_scale(ray->dir, ray->tnear));
    double org[3] = {p0.x, p0.y, p0.z}, dir[3] = {ray->dir.x, ray->dir.y, ray->dir.z};
    double lo[3] = {o->box_lo.x, o->box_lo.y, o->box_lo.z}, hi[3] = {o->box_hi.x, o->box_hi.y, o->box_hi.z};
    if (!o->has_clear_box) return 0;
    for (int a = 0; a < 3; ++a)
        if (!(org[a] > lo[a] && org[a] < hi[a])) return 0; /* not strictly inside: the scene query decides */
    double t = INFINITY;
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
        double ta = dir[a] > 0 ? (hi[a] - org[a]) / dir[a] : dir[a] < 0 ? (lo[a] - org[a]) / dir[a] : INFINITY;
        if (ta < t) {
            t = ta;
            axis = a;
        }
    }
    t += ray->tnear;
    *found = 0;
    if (axis < 0 || !(t > ray->tnear && t < ray->tfar)) return 1;
    soak_vec3 pe = soak_v3_add(ray->org, soak_v3_scale(ray->dir, t));
    double n[3] = {0, 0, 0}, p[3] = {pe.x, pe.y, pe.z};
    n[axis] = dir[axis] > 0 ? 1.0 : -1.0;
    p[axis] = dir[axis] > 0 ? hi[axis] : lo[axis];
    hit->t = t;
    hit->p = soak_v3(p[0], p[1], p[2]);
    hit->ng = hit->ns = soak_v3(n[0], n[1], n[2]);
    hit->u = hit->v = 0;
    hit->prim_id = 0;
    hit->object_id = object_id;
    *found = 1;
    return 1;
}

static int in_clear_box(const geo_object *o, soak_vec3 p)
{
    return p.x > o->clear_lo.x && p.x < o->clear_hi.x && p.y > o->clear_lo.y && p.y < o->clear_hi.y &&
           p.z > o->clear_lo.z && p.z < o->clear_hi.z;
}

double geo_clear_box_distance(const geo_object *o, soak_vec3 p)
{
    if (!o->has_clear_box || !in_clear_box(o, p)) return 0.0;
    double dx = fmin(p.x - o->clear_lo.x, o->clear_hi.x - p.x);
    double dy = fmin(p.y - o->clear_lo.y, o->clear_hi.y - p.y);
    double dz = fmin(p.z - o->clear_lo.z, o->clear_hi.z - p.z);
    return fmin(dx, fmin(dy, dz));
}

int geo_segment_in_clear_box(const geo_object *o, soak_vec3 a, soak_vec3 b)
{
    return o->has_clear_box && in_clear_box(o, a) && in_clear_box(o, b);
}
