/* The clear box of a box object (soak/geometry.h, soak_geometry_clear_distance):
 * its interior, less a margin above Embree's float error (the scale of
 * soak_geometry_offset's, as for the clear ball), when no other object's
 * bounds meet it. A box is convex, so a segment with both ends in it meets
 * no surface, and the distance from a point in it to the nearest face is
 * the smallest of six coordinate differences. The inscribed ball of a thin
 * sheet covers only its middle; a walk in the sheet spends a fifth of its
 * work on occlusion rays that this answers without traversal. */
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
