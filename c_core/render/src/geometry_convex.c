/* Closed convex triangle meshes (a scanned pebble, Blender's UV sphere): found
 * at commit, then a walk's exit queries from inside are answered by stepping
 * across neighbouring faces from a face near the answer instead of traversing
 * the BVH (geometry_local.c). The first face tried is a direction map's: the
 * face seen from the vertices' mean in each cell of a cube map, looked up
 * where the ray leaves the sphere of the vertices' mean radius (on the
 * benchmark's UV sphere 1.6 steps per query on average).
 *
 * Seen from a point x inside a convex polyhedron, its faces are cones that
 * tile the directions around x once, and the ray from x along d leaves
 * through the one face whose cone holds d. Sign tests of d against a face's
 * three edge planes through x say whether it does, and if not, across which
 * edge lies the face to try next: a walk over the face adjacency, the
 * point location of a triangulated sphere (the "visibility walk",
 * Devillers, Pion and Teillaud, Walking in a triangulation, Int. J. Found.
 * Comput. Sci. 13(2), 2002). It may circle on a badly shaped triangulation,
 * so it is capped at GEO_CONVEX_MAX_STEPS and the caller then asks the BVH.
 *
 * The mesh qualifies when it is closed (every edge shared by exactly two faces,
 * in opposite directions, vertices matched by position), every edge is convex
 * (no neighbour's far vertex above a face's plane), and the mean of its
 * vertices lies strictly inside every face's plane with the faces' solid
 * angles about it summing to 4 pi: the central projection from it is then one
 * to one, the surface is star-shaped and, convex at every edge, bounds a
 * convex body. Its queries may skip the rest of the scene when no other
 * object's bounds reach into that body (separated by an axis or by one of its
 * face planes). */
#include "geometry_internal.h"

#include <stdlib.h>

typedef struct pos_key {
    double x, y, z;
    unsigned index;
} pos_key;

typedef struct edge_key {
    unsigned lo, hi;    /* canonical vertex ids, lo < hi */
    unsigned tri, side; /* face and which of its edges (side i: vertex i to i + 1) */
    int forward;        /* the face runs the edge lo -> hi */
} edge_key;

static int cmp_pos(const void *pa, const void *pb)
{
    const pos_key *a = pa, *b = pb;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    if (a->z != b->z) return a->z < b->z ? -1 : 1;
    return (a->index > b->index) - (a->index < b->index);
}

static int cmp_edge(const void *pa, const void *pb)
{
    const edge_key *a = pa, *b = pb;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    return (a->hi > b->hi) - (a->hi < b->hi);
}

/* Vertex ids with duplicates (same position: split at a seam by normals or
 * texture coordinates) mapped to one; NULL without memory. */
static unsigned *canonical_vertices(const geo_object *o)
{
    pos_key *k = malloc(o->nv * sizeof *k);
    unsigned *canon = malloc(o->nv * sizeof *canon);
    if (!k || !canon) {
        free(k);
        free(canon);
        return NULL;
    }
    for (size_t i = 0; i < o->nv; ++i)
        k[i] = (pos_key){o->pos[3 * i], o->pos[3 * i + 1], o->pos[3 * i + 2], (unsigned)i};
    qsort(k, o->nv, sizeof *k, cmp_pos);
    for (size_t i = 0; i < o->nv; ++i) {
        int same = i > 0 && k[i].x == k[i - 1].x && k[i].y == k[i - 1].y && k[i].z == k[i - 1].z;
        canon[k[i].index] = same ? canon[k[i - 1].index] : k[i].index;
    }
    free(k);
    return canon;
}

/* Face adjacency of a closed, consistently oriented mesh: adj[3 t + i] is the
 * face across side i of face t, followed by extra unset entries. NULL when the mesh is open, non-manifold,
 * inconsistently wound or degenerate, or without memory. */
static unsigned *face_adjacency(const geo_object *o, size_t extra)
{
    unsigned *canon = canonical_vertices(o);
    edge_key *e = malloc(3 * o->nt * sizeof *e);
    unsigned *adj = malloc((3 * o->nt + extra) * sizeof *adj);
    int ok = canon && e && adj && (3 * o->nt) % 2 == 0;
    for (size_t t = 0; ok && t < o->nt; ++t)
        for (unsigned i = 0; i < 3; ++i) {
            unsigned a = canon[o->idx[3 * t + i]], b = canon[o->idx[3 * t + (i + 1) % 3]];
            ok = ok && a != b;
            e[3 * t + i] = (edge_key){a < b ? a : b, a < b ? b : a, (unsigned)t, i, a < b};
        }
    if (ok) qsort(e, 3 * o->nt, sizeof *e, cmp_edge);
    for (size_t i = 0; ok && i < 3 * o->nt; i += 2) {
        const edge_key *p = &e[i], *q = &e[i + 1];
        int last = i + 2 >= 3 * o->nt;
        ok = cmp_edge(p, q) == 0 && p->forward != q->forward && (last || cmp_edge(q, &e[i + 2]) != 0);
        if (ok) {
            adj[3 * p->tri + p->side] = q->tri;
            adj[3 * q->tri + q->side] = p->tri;
        }
    }
    free(canon);
    free(e);
    if (!ok) {
        free(adj);
        return NULL;
    }
    return adj;
}

static double det3(soak_vec3 a, soak_vec3 b, soak_vec3 c) { return soak_v3_dot(a, soak_v3_cross(b, c)); }

/* Solid angle of triangle (a, b, c) seen from the origin, signed by its
 * winding: Van Oosterom and Strackee, The solid angle of a plane triangle,
 * IEEE Trans. Biomed. Eng. 30(2), 1983, eq. 8. */
static double solid_angle(soak_vec3 a, soak_vec3 b, soak_vec3 c)
{
    double la = soak_v3_len(a), lb = soak_v3_len(b), lc = soak_v3_len(c);
    double den = la * lb * lc + soak_v3_dot(a, b) * lc + soak_v3_dot(a, c) * lb + soak_v3_dot(b, c) * la;
    return 2.0 * atan2(det3(a, b, c), den);
}

/* The convexity tests of the file's top comment on a closed mesh with
 * adjacency adj; sets o->orient (+1: faces wound counter-clockwise seen from
 * outside). Returns 1 when they all pass. */
static int closed_mesh_convex(geo_object *o, const unsigned *adj)
{
    soak_vec3 c = soak_v3(0, 0, 0);
    double scale = 0;
    for (size_t i = 0; i < o->nv; ++i) c = soak_v3_add(c, vtx(o->pos, (unsigned)i));
    c = soak_v3_scale(c, 1.0 / (double)o->nv);
    double mean_r = 0;
    for (size_t i = 0; i < o->nv; ++i) {
        double r = soak_v3_len(soak_v3_sub(vtx(o->pos, (unsigned)i), c));
        scale = fmax(scale, r);
        mean_r += r / (double)o->nv;
    }
    o->map_c = c;
    o->map_r = mean_r;
    /* Edges may bend inward by rounding: a modeller computing in float leaves
     * its planar quads bent by about 1e-7, which the normal of a thin face
     * near a pole turns into heights up to 2e-6 of the radius (Blender's UV
     * sphere). Tolerated up to 1e-5 of the size: the exit found may then lie
     * that far from the BVH's, a difference no image shows. */
    double reach = scale + fmax(fmax(fabs(c.x), fabs(c.y)), fabs(c.z));
    double volume = 0, omega = 0, tol = 1e-9 * scale, tol_reflex = 1e-5 * reach;
    for (size_t t = 0; t < o->nt; ++t) {
        const unsigned *f = o->idx + 3 * t;
        volume += det3(soak_v3_sub(vtx(o->pos, f[0]), c), soak_v3_sub(vtx(o->pos, f[1]), c),
                       soak_v3_sub(vtx(o->pos, f[2]), c));
    }
    if (!(fabs(volume) > 0) || !(scale > 0)) return 0;
    o->orient = volume > 0 ? 1 : -1;
    for (size_t t = 0; t < o->nt; ++t) {
        const unsigned *f = o->idx + 3 * t;
        soak_vec3 p0 = vtx(o->pos, f[0]), p1 = vtx(o->pos, f[1]), p2 = vtx(o->pos, f[2]);
        soak_vec3 n = soak_v3_scale(soak_v3_cross(soak_v3_sub(p1, p0), soak_v3_sub(p2, p0)), o->orient);
        double ln = soak_v3_len(n);
        if (!(ln > 0) || !(soak_v3_dot(n, soak_v3_sub(p0, c)) > tol * ln)) return 0; /* c strictly inside */
        n = soak_v3_scale(n, 1.0 / ln);
        for (unsigned i = 0; i < 3; ++i) {
            const unsigned *g = o->idx + 3 * adj[3 * t + i];
            for (unsigned k = 0; k < 3; ++k)
                if (soak_v3_dot(n, soak_v3_sub(vtx(o->pos, g[k]), p0)) > tol_reflex) return 0; /* a reflex edge */
        }
        omega += o->orient * solid_angle(soak_v3_sub(p0, c), soak_v3_sub(p1, c), soak_v3_sub(p2, c));
    }
    return fabs(omega - 4 * SOAK_PI) < 1e-6;
}

static int walk_to_face(const geo_object *o, soak_vec3 x, soak_vec3 d, unsigned *face, long max_steps);

/* Cell of direction v (not zero) in a cube map of n x n cells per face. */
static unsigned map_cell(int n, soak_vec3 v)
{
    double ax = fabs(v.x), ay = fabs(v.y), az = fabs(v.z), m, a, b;
    int face;
    if (ax >= ay && ax >= az) {
        face = v.x > 0 ? 0 : 1, m = ax, a = v.y, b = v.z;
    } else if (ay >= az) {
        face = v.y > 0 ? 2 : 3, m = ay, a = v.z, b = v.x;
    } else {
        face = v.z > 0 ? 4 : 5, m = az, a = v.x, b = v.y;
    }
    int i = (int)((a / m + 1) * 0.5 * n), j = (int)((b / m + 1) * 0.5 * n);
    i = i < 0 ? 0 : i >= n ? n - 1 : i;
    j = j < 0 ? 0 : j >= n ? n - 1 : j;
    return (unsigned)((face * n + j) * n + i);
}

/* Centre direction of cell (face, j, i), the inverse of map_cell. */
static soak_vec3 cell_dir(int n, int face, int j, int i)
{
    double a = 2.0 * (i + 0.5) / n - 1, b = 2.0 * (j + 0.5) / n - 1, sgn = face % 2 ? -1.0 : 1.0;
    if (face < 2) return soak_v3(sgn, a, b);
    if (face < 4) return soak_v3(b, sgn, a);
    return soak_v3(a, b, sgn);
}

/* The face each cube-map cell's centre direction leaves through from the
 * vertices' mean, found by walks from the previous cell's face (neighbours
 * mostly); a cell whose walk gives up keeps the face it reached. */
static void fill_direction_map(geo_object *o)
{
    unsigned face = 0;
    for (int f = 0; f < 6; ++f)
        for (int j = 0; j < o->map_n; ++j)
            for (int i = 0; i < o->map_n; ++i) {
                walk_to_face(o, o->map_c, cell_dir(o->map_n, f, j, i), &face, (long)o->nt + 3);
                o->dir_map[(f * o->map_n + j) * o->map_n + i] = face;
            }
}

/* Start face for the exit of ray: where it meets the sphere of the vertices'
 * mean radius (exact for a sphere-like mesh, a guess otherwise), looked up in
 * the direction map. */
static unsigned start_face(const geo_object *o, const soak_ray *ray)
{
    soak_vec3 oc = soak_v3_sub(ray->org, o->map_c), d = ray->dir;
    double A = soak_v3_dot(d, d), B = soak_v3_dot(oc, d), C = soak_v3_dot(oc, oc) - o->map_r * o->map_r;
    double disc = B * B - A * C;
    soak_vec3 v = d;
    if (disc >= 0) {
        double t = (-B + sqrt(disc)) / A; /* the far root: leaving the sphere */
        if (t > 0) v = soak_v3_add(oc, soak_v3_scale(d, t));
    }
    if (!(soak_v3_dot(v, v) > 0)) v = d;
    return o->dir_map[map_cell(o->map_n, v)];
}

void geo_mark_convex(soak_geometry *g, unsigned id)
{
    geo_object *o = &g->objects[id];
    free(o->adj);
    o->adj = o->dir_map = NULL;
    o->convex_isolated = 0;
    if (o->kind != SOAK_SHAPE_MESH || o->nt < 4) return;
    /* About one cell per face. */
    int n = (int)ceil(sqrt((double)o->nt / 6.0));
    n = n < 4 ? 4 : n > 128 ? 128 : n;
    unsigned *adj = face_adjacency(o, (size_t)6 * n * n);
    if (!adj) return;
    if (!closed_mesh_convex(o, adj)) {
        free(adj);
        return;
    }
    o->adj = adj;
    o->dir_map = adj + 3 * o->nt;
    o->map_n = n;
    fill_direction_map(o);
}

/* 1 when the box [lo, hi] (another object's bounds) does not reach into the
 * interior of convex object o: apart along an axis, or beyond one of its
 * face planes (touching allowed, within tol). */
static int box_outside_convex(const geo_object *o, soak_vec3 olo, soak_vec3 ohi, soak_vec3 lo, soak_vec3 hi, double tol)
{
    if (olo.x >= hi.x - tol || lo.x >= ohi.x - tol || olo.y >= hi.y - tol || lo.y >= ohi.y - tol ||
        olo.z >= hi.z - tol || lo.z >= ohi.z - tol)
        return 1;
    for (size_t t = 0; t < o->nt; ++t) {
        const unsigned *f = o->idx + 3 * t;
        soak_vec3 p0 = vtx(o->pos, f[0]);
        soak_vec3 n = soak_v3_norm(soak_v3_scale(
            soak_v3_cross(soak_v3_sub(vtx(o->pos, f[1]), p0), soak_v3_sub(vtx(o->pos, f[2]), p0)), o->orient));
        int all_out = 1;
        for (int k = 0; k < 8 && all_out; ++k) {
            soak_vec3 q = soak_v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
            all_out = soak_v3_dot(n, soak_v3_sub(q, p0)) >= -tol;
        }
        if (all_out) return 1;
    }
    return 0;
}

void geo_mark_convex_isolated(soak_geometry *g, unsigned id)
{
    geo_object *o = &g->objects[id];
    soak_vec3 olo = o->bound_lo, ohi = o->bound_hi;
    o->convex_isolated = 0;
    if (!o->adj) return;
    double m =
        fmax(fmax(fmax(fabs(olo.x), fabs(olo.y)), fmax(fabs(olo.z), fabs(ohi.x))), fmax(fabs(ohi.y), fabs(ohi.z)));
    double tol = 1e-9 * (1 + m);
    for (unsigned j = 0; j < g->count; ++j) {
        if (j != id && !box_outside_convex(o, olo, ohi, g->objects[j].bound_lo, g->objects[j].bound_hi, tol)) return;
    }
    o->convex_isolated = 1;
}

/* Walks from *face toward the face whose cone from x holds d; 1 when found
 * within max_steps (*face is then it), 0 with *face the last face reached.
 * Where rounding bends an edge inward, d can fall in the sliver between two
 * neighbours' cones and each sends the walk to the other: the face the walk
 * would return to is then as good as the one it is on (the sliver is as
 * narrow as the bend), and it stops there. */
static int walk_to_face(const geo_object *o, soak_vec3 x, soak_vec3 d, unsigned *face, long max_steps)
{
    unsigned t = *face, prev = (unsigned)-1;
    for (long step = 0; step < max_steps; ++step) {
        const unsigned *f = o->idx + 3 * t;
        soak_vec3 a = soak_v3_sub(vtx(o->pos, f[0]), x), b = soak_v3_sub(vtx(o->pos, f[1]), x);
        soak_vec3 c = soak_v3_sub(vtx(o->pos, f[2]), x);
        double e[3] = {o->orient * det3(a, b, d), o->orient * det3(b, c, d), o->orient * det3(c, a, d)};
        int worst = e[0] <= e[1] ? (e[0] <= e[2] ? 0 : 2) : (e[1] <= e[2] ? 1 : 2);
        unsigned next = o->adj[3 * t + worst];
        if (!(e[worst] < 0) || next == prev) {
            *face = t;
            return 1;
        }
        prev = t;
        t = next;
    }
    *face = t;
    return 0;
}

int geo_convex_exit(const geo_object *o, unsigned object_id, const soak_ray *ray, soak_hit *hit, int *found)
{
    unsigned t = start_face(o, ray);
    soak_vec3 x = ray->org, d = ray->dir;
    if (!walk_to_face(o, x, d, &t, GEO_CONVEX_MAX_STEPS)) return 0;
    const unsigned *f = o->idx + 3 * t;
    soak_vec3 p0 = vtx(o->pos, f[0]);
    soak_vec3 n = soak_v3_cross(soak_v3_sub(vtx(o->pos, f[1]), p0), soak_v3_sub(vtx(o->pos, f[2]), p0));
    double dn = soak_v3_dot(d, n), th = soak_v3_dot(soak_v3_sub(p0, x), n) / dn;
    /* d leaves through this face, and x lies inside its plane. */
    if (!(o->orient * dn > 0) || !(th > ray->tnear) || !soak_is_finite(th)) return 0;
    *found = th < ray->tfar;
    if (*found) {
        hit->t = th;
        hit->p = soak_v3_add(x, soak_v3_scale(d, th));
        hit->ng = soak_v3_norm(n);
        hit->ns = hit->ng;
        hit->u = hit->v = 0;
        hit->prim_id = t;
        hit->object_id = object_id;
    }
    return 1;
}
