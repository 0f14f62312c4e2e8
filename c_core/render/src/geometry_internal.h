/* Private to the geometry files (soak/geometry.h): the object store, the
 * Embree scene, and the small helpers every concern shares. The concerns:
 * geometry.c builds the Embree scene (meshes, quads, boxes, commit),
 * geometry_sphere.c the analytic spheres (Embree user geometry),
 * geometry_isolation.c the nearest-surface analysis at commit (isolated
 * spheres, clear balls), geometry_query.c the ray queries and packets,
 * geometry_local.c the shortcuts for a walk inside one object. */
#ifndef SOAK_GEOMETRY_INTERNAL_H
#define SOAK_GEOMETRY_INTERNAL_H

#include <embree3/rtcore.h>
#include <math.h>

#include "soak/geometry.h"

typedef struct geo_object {
    soak_shape_kind kind;
    size_t nv, nt;
    double *pos; /* 3 nv */
    double *nrm; /* 3 nv or NULL */
    double *uv;  /* 2 nv or NULL */
    unsigned *idx;
    soak_vec3 center; /* spheres */
    double radius;
    int isolated; /* no other surface enters the interior (spheres; set at commit) */
    soak_vec3 clear_c; /* a ball no surface enters (set at commit; clear_r2 = 0: none) */
    double clear_r2;
    int has_clear_box; /* boxes: clear_lo..clear_hi meets no surface (geometry_clear_box.c) */
    soak_vec3 clear_lo, clear_hi;
    soak_vec3 box_lo, box_hi; /* the box's own bounds, with has_clear_box */
    unsigned *adj;        /* closed convex meshes: face across each side (3 nt), else NULL */
    int orient;           /* with adj: +1 faces wound counter-clockwise from outside, -1 clockwise */
    int convex_isolated;  /* with adj: no other object's bounds reach into the body */
    unsigned *dir_map;    /* with adj (same block): the face seen from map_c in each cube-map cell */
    int map_n;            /* cells per cube face side */
    soak_vec3 map_c;      /* the vertices' mean, inside the body */
    double map_r;         /* the vertices' mean distance from map_c */
    soak_vec3 bound_lo, bound_hi; /* the object's bounds (set at commit) */
} geo_object;

struct soak_geometry {
    RTCDevice device;
    RTCScene scene;
    geo_object *objects;
    unsigned count, capacity;
    int committed;
    int robust; /* Embree's robust traversal (on unless soak_geometry_set_robust turns it off) */
    char error[256]; /* last Embree device error, written by its callback */
};

static inline soak_vec3 vtx(const double *a, unsigned i) { return soak_v3(a[3 * i], a[3 * i + 1], a[3 * i + 2]); }

static inline int vec_ok(soak_vec3 v) { return soak_is_finite(v.x) && soak_is_finite(v.y) && soak_is_finite(v.z); }

/* Sphere roots of |o + t d - c|^2 = r^2 in double; returns the count of real
 * roots, t0 <= t1. Uses the numerically stable form (no cancellation). */
static inline int sphere_roots(soak_vec3 c, double r, soak_vec3 o, soak_vec3 d, double *t0, double *t1)
{
    soak_vec3 oc = soak_v3_sub(o, c);
    double A = soak_v3_dot(d, d), B = soak_v3_dot(oc, d), Cc = soak_v3_dot(oc, oc) - r * r;
    /* Discriminant from the perpendicular distance: less cancellation far away. */
    soak_vec3 perp = soak_v3_sub(oc, soak_v3_scale(d, B / A));
    double disc = A * (r * r - soak_v3_dot(perp, perp));
    if (!(A > 0) || disc < 0) return 0;
    double q = -(B + copysign(sqrt(disc), B));
    double a0 = q / A, a1 = q != 0 ? Cc / q : a0;
    *t0 = fmin(a0, a1);
    *t1 = fmax(a0, a1);
    return 2;
}

/* Outward normal and (longitude, colatitude) texture coordinates at p. */
static inline void sphere_surface(const geo_object *o, soak_vec3 p, soak_vec3 *ng, double *u, double *v)
{
    soak_vec3 n = soak_v3_norm(soak_v3_sub(p, o->center));
    double phi = atan2(n.y, n.x);
    *ng = n;
    *u = (phi < 0 ? phi + 2 * SOAK_PI : phi) / (2 * SOAK_PI);
    *v = acos(fmax(-1.0, fmin(1.0, n.z))) / SOAK_PI;
}

static inline int ray_ok(const soak_ray *r)
{
    return vec_ok(r->org) && vec_ok(r->dir) && soak_v3_dot(r->dir, r->dir) > 0 && soak_in_range(r->tnear, 0, 1e300) &&
           r->tfar > r->tnear;
}

static inline void to_embree(const soak_ray *r, struct RTCRay *e)
{
    e->org_x = (float)r->org.x;
    e->org_y = (float)r->org.y;
    e->org_z = (float)r->org.z;
    e->dir_x = (float)r->dir.x;
    e->dir_y = (float)r->dir.y;
    e->dir_z = (float)r->dir.z;
    e->tnear = (float)r->tnear;
    e->tfar = r->tfar > 3e38 ? INFINITY : (float)r->tfar;
    e->time = 0;
    e->mask = 0xFFFFFFFFu;
    e->id = 0;
    e->flags = 0;
}

/* geometry.c: a zeroed slot for a new object (NULL without memory), and
 * Embree's side of it: commits geom and attaches it as object g->count. */
geo_object *geo_push_object(soak_geometry *g);
soak_status geo_commit_and_attach(soak_geometry *g, RTCGeometry geom, unsigned *object_id);
/* geometry_isolation.c, run at commit: the isolated flag of every sphere
 * (SOAK_ERR_NOMEM when its sort has no memory) and the clear ball of
 * triangle object id. */
soak_status geo_mark_isolated(soak_geometry *g);
void geo_mark_clear_ball(soak_geometry *g, unsigned id);
/* geometry_clear_box.c, run at commit: the clear box of box object id; the
 * distance from p to its faces (0 outside it or without one) and whether a
 * segment lies inside it. */
void geo_mark_clear_box(soak_geometry *g, unsigned id);
double geo_clear_box_distance(const geo_object *o, soak_vec3 p);
int geo_segment_in_clear_box(const geo_object *o, soak_vec3 a, soak_vec3 b);
/* The first hit of a ray starting strictly inside a box with a clear box
 * (its exit face, outward normal, no texture coordinates), in closed form;
 * 0 when it does not apply (the caller asks the scene). */
int geo_box_exit(const geo_object *o, unsigned object_id, const soak_ray *ray, soak_hit *hit, int *found);
/* geometry_convex.c, run at commit: adj, orient and the direction map of a
 * closed convex mesh, then (after every object is in) whether it is isolated;
 * and the exit of a ray from inside such a mesh, found by walking faces from
 * the direction map's guess: 1 with *found set when answered (want_uv = 0
 * form: u = v = 0, ns = ng), 0 when the walk gave up or the origin is not
 * inside (the caller asks the BVH). */
#define GEO_CONVEX_MAX_STEPS 32
/* Objects past which soak_geometry_ray_escapes asks the BVH instead of
 * testing every other object's bounds. */
#define GEO_ESCAPE_MAX_OBJECTS 16
void geo_mark_convex(soak_geometry *g, unsigned id);
void geo_mark_convex_isolated(soak_geometry *g, unsigned id);
int geo_convex_exit(const geo_object *o, unsigned object_id, const soak_ray *ray, soak_hit *hit, int *found);
/* geometry_query.c: the closest hit in the whole scene; detail 0 skips the
 * texture coordinates and the shading normal (a walk's boundary query). */
soak_status geo_intersect_scene(const soak_geometry *g, const soak_ray *ray, int detail, soak_hit *hit, int *found);

#endif
