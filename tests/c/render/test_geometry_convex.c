/* Convex meshes in the walk's local queries (issue 50, item 1): a closed
 * convex mesh that no other object reaches into is answered by a walk over
 * its faces instead of the BVH (geometry_convex.c). Reference: the whole
 * scene's BVH query (soak_geometry_intersect / _occluded), a second method,
 * for random rays from random points inside; and the rule itself for which
 * meshes qualify (closed and convex, nothing else inside). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "soak/geometry.h"

#define SEGS 48
#define RINGS 24

/* A UV sphere of radius r about c as Blender builds it: poles shared, rings
 * of SEGS vertices, quads split in two; dent > 0 pushes one equator vertex
 * in by that fraction (a reflex region). Returns 0 without memory. */
static int uv_sphere(soak_mesh *m, soak_vec3 c, double r, double dent)
{
    size_t nv = 2 + (size_t)SEGS * (RINGS - 1), nt = 2 * (size_t)SEGS * (RINGS - 1);
    m->positions = malloc(3 * nv * sizeof *m->positions);
    m->indices = malloc(3 * nt * sizeof *m->indices);
    m->normals = m->uvs = NULL;
    m->tri_uv = NULL;
    if (!m->positions || !m->indices) return 0;
    m->n_vertices = nv;
    m->n_triangles = nt;
    double *p = m->positions;
    p[0] = c.x, p[1] = c.y, p[2] = c.z + r; /* north pole: vertex 0 */
    p[3] = c.x, p[4] = c.y, p[5] = c.z - r; /* south pole: vertex 1 */
    for (int i = 1; i < RINGS; ++i)
        for (int j = 0; j < SEGS; ++j) {
            double th = SOAK_PI * i / RINGS, ph = 2 * SOAK_PI * j / SEGS;
            double rr = (dent > 0 && i == RINGS / 2 && j == 0) ? r * (1 - dent) : r;
            double *v = p + 3 * (2 + (size_t)(i - 1) * SEGS + j);
            v[0] = c.x + rr * sin(th) * cos(ph), v[1] = c.y + rr * sin(th) * sin(ph), v[2] = c.z + rr * cos(th);
        }
    unsigned *t = m->indices;
#define RV(i, j) (2u + (unsigned)((i)-1) * SEGS + (unsigned)((j) % SEGS))
    for (int j = 0; j < SEGS; ++j) { /* outward (counter-clockwise from outside) */
        *t++ = 0, *t++ = RV(1, j), *t++ = RV(1, j + 1);
        *t++ = 1, *t++ = RV(RINGS - 1, j + 1), *t++ = RV(RINGS - 1, j);
    }
    for (int i = 1; i < RINGS - 1; ++i)
        for (int j = 0; j < SEGS; ++j) {
            *t++ = RV(i, j), *t++ = RV(i + 1, j), *t++ = RV(i + 1, j + 1);
            *t++ = RV(i, j), *t++ = RV(i + 1, j + 1), *t++ = RV(i, j + 1);
        }
#undef RV
    return 1;
}

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static double uniform(void) /* xorshift64*: the test's own stream */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1Dull) >> 11) / 9007199254740992.0;
}

static soak_vec3 random_dir(void)
{
    double z = 2 * uniform() - 1, ph = 2 * SOAK_PI * uniform(), s = sqrt(fmax(0.0, 1 - z * z));
    return soak_v3(s * cos(ph), s * sin(ph), z);
}

/* Random rays from points inside the ball of radius 0.97 r about c: local
 * and scene queries agree on hit, distance and face plane; occlusion of
 * random segments agrees away from the surface. */
static void compare_queries(const soak_geometry *g, unsigned id, soak_vec3 c, double r, const char *what)
{
    int n = 4000, hit_miss = 0, occl_miss = 0, checked = 0;
    double worst_t = 0, worst_n = 0;
    for (int k = 0; k < n; ++k) {
        soak_vec3 x = soak_v3_add(c, soak_v3_scale(random_dir(), 0.97 * r * cbrt(uniform())));
        soak_ray ray = {x, random_dir(), 0.0, INFINITY};
        soak_hit a, b;
        int fa = 0, fb = 0;
        soak_geometry_intersect_local(g, id, &ray, 0, &a, &fa);
        soak_geometry_intersect(g, &ray, &b, &fb);
        if (!fa || !fb || b.object_id != id) {
            hit_miss++;
            continue;
        }
        worst_t = fmax(worst_t, fabs(a.t - b.t) / b.t);
        worst_n = fmax(worst_n, 1 - fabs(soak_v3_dot(a.ng, b.ng)));
        soak_ray seg = ray;
        seg.tfar = b.t * (uniform() < 0.5 ? 0.9 : 1.1); /* clearly short of or past the exit */
        int oa = -1, ob = -2;
        soak_geometry_occluded_local(g, id, &seg, &oa);
        soak_geometry_occluded(g, &seg, &ob);
        occl_miss += oa != ob;
        checked++;
    }
    char msg[200];
    snprintf(msg, sizeof msg, "%s: every ray from inside finds the object's surface both ways", what);
    check_true(msg, hit_miss == 0 && checked == n);
    snprintf(msg, sizeof msg, "%s: exit distance, local vs BVH (relative)", what);
    check_close(msg, worst_t, 0.0, 1e-6);
    snprintf(msg, sizeof msg, "%s: exit face plane, 1 - |n_local . n_BVH|", what);
    /* faces meeting at an edge the ray grazes may differ: their normals are
     * 2 pi / SEGS apart at most */
    check_close(msg, worst_n, 0.0, 1 - cos(2 * SOAK_PI / SEGS) + 1e-9);
    snprintf(msg, sizeof msg, "%s: segment occlusion, local vs BVH disagreements", what);
    check_true(msg, occl_miss == 0);
}

int main(void)
{
    soak_geometry *g = NULL;
    char err[256] = "";
    if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK)) return check_finish();
    soak_mesh ball, dented, holder;
    soak_vec3 c_ball = soak_v3(0, 0, 1.0), c_dent = soak_v3(5, 0, 1.0), c_hold = soak_v3(10, 0, 1.0);
    if (!check_true("memory", uv_sphere(&ball, c_ball, 1.0, 0) && uv_sphere(&dented, c_dent, 1.0, 0.2) &&
                                  uv_sphere(&holder, c_hold, 1.0, 0))) {
        soak_geometry_destroy(g);
        return check_finish();
    }
    unsigned id_ball, id_dent, id_hold, id_floor, id_inner;
    soak_geometry_add_mesh(g, &ball, NULL, &id_ball);
    soak_geometry_add_mesh(g, &dented, NULL, &id_dent);
    soak_geometry_add_mesh(g, &holder, NULL, &id_hold);
    /* the floor touches every ball at its south pole, reaching into none */
    soak_geometry_add_quad(g, soak_v3(-10, -10, 0), soak_v3(30, 0, 0), soak_v3(0, 20, 0), &id_floor);
    soak_geometry_add_sphere(g, c_hold, 0.3, &id_inner); /* inside the holder */
    if (check_status("commit", soak_geometry_commit(g), SOAK_OK)) {
        check_true("closed convex mesh resting on the floor: local queries skip the BVH",
                   soak_geometry_object_isolated(g, id_ball));
        check_true("dented mesh (one vertex 20 % in): not convex, the BVH answers",
                   !soak_geometry_object_isolated(g, id_dent));
        check_true("convex mesh holding a sphere: not isolated, the BVH answers",
                   !soak_geometry_object_isolated(g, id_hold));
        compare_queries(g, id_ball, c_ball, 1.0 * cos(SOAK_PI / RINGS), "convex UV sphere");
        compare_queries(g, id_dent, c_dent, 0.8 * cos(SOAK_PI / RINGS), "dented UV sphere");
    }
    free(ball.positions), free(ball.indices), free(dented.positions), free(dented.indices);
    free(holder.positions), free(holder.indices);
    soak_geometry_destroy(g);
    return check_finish();
}
