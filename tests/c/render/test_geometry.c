/* Geometry: analytic sphere/quad/box distances, normals and UVs, local
 * queries and the isolation rule, robust modes and clear distances
 * (meshes, threads and batched occlusion: test_geometry_mesh.c). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "geometry_cases.h"
#include "soak/geometry.h"

static void test_sphere(void)
{
    soak_geometry *g = NULL;
    char err[256] = "";
    if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK) || !g) return;
    unsigned id = 99;
    check_status("add sphere", soak_geometry_add_sphere(g, soak_v3(0, 0, 0), 1.0, &id), SOAK_OK);
    check_true("sphere id 0", id == 0);
    check_status("commit", soak_geometry_commit(g), SOAK_OK);

    /* Ray from (0.3, 0.4, -5) along +z hits at z = -sqrt(1 - 0.25): t = 5 - sqrt(0.75). */
    soak_ray r = geo_ray(soak_v3(0.3, 0.4, -5), soak_v3(0, 0, 1));
    soak_hit h;
    int found = 0;
    check_status("intersect", soak_geometry_intersect(g, &r, &h, &found), SOAK_OK);
    check_true("sphere hit", found);
    if (found) {
        check_close("sphere t analytic", h.t, 5.0 - sqrt(0.75), 1e-12);
        check_close("normal = position", h.ng.x, 0.3, 1e-12);
        check_close("normal z", h.ng.z, -sqrt(0.75), 1e-12);
        check_close("uv u = atan2(y,x)/2pi", h.u, atan2(0.4, 0.3) / (2 * SOAK_PI), 1e-12);
        check_close("uv v = theta/pi", h.v, acos(-sqrt(0.75)) / SOAK_PI, 1e-12);
    }
    /* Oblique, non-unit direction from far away: t in units of |dir|. */
    soak_vec3 d = soak_v3(-2, -1, -2); /* |d| = 3 */
    soak_ray r2 = geo_ray(soak_v3(20, 10, 20), d);
    check_status("intersect far", soak_geometry_intersect(g, &r2, &h, &found), SOAK_OK);
    check_true("far hit", found);
    if (found) check_close("far t = (30 - 1)/3", h.t, 29.0 / 3.0, 1e-12);
    /* From inside: the exit distance is the radius. */
    soak_ray r3 = geo_ray(soak_v3(0, 0, 0), soak_v3(0, 1, 0));
    check_status("intersect inside", soak_geometry_intersect(g, &r3, &h, &found), SOAK_OK);
    check_true("inside hit", found && fabs(h.t - 1.0) < 1e-12 && h.ng.y > 0.999999);
    /* Miss, occlusion and tfar limits. */
    soak_ray miss = geo_ray(soak_v3(1.01, 0, -5), soak_v3(0, 0, 1));
    check_status("intersect miss", soak_geometry_intersect(g, &miss, &h, &found), SOAK_OK);
    check_true("miss", !found);
    int occ = -1;
    soak_ray shadow = geo_ray(soak_v3(0, 0, -5), soak_v3(0, 0, 1));
    shadow.tfar = 3.9;
    check_status("occluded", soak_geometry_occluded(g, &shadow, &occ), SOAK_OK);
    check_true("not occluded before t=4", occ == 0);
    shadow.tfar = 4.1;
    soak_geometry_occluded(g, &shadow, &occ);
    check_true("occluded past t=4", occ == 1);
    /* Bad rays. */
    soak_ray bad = geo_ray(soak_v3(NAN, 0, 0), soak_v3(0, 0, 1));
    check_status("NaN origin", soak_geometry_intersect(g, &bad, &h, &found), SOAK_ERR_ARG);
    bad = geo_ray(soak_v3(0, 0, 0), soak_v3(0, 0, 0));
    check_status("zero direction", soak_geometry_intersect(g, &bad, &h, &found), SOAK_ERR_ARG);
    check_status("negative radius", soak_geometry_add_sphere(g, soak_v3(0, 0, 0), -1, NULL), SOAK_ERR_ARG);
    check_status("NaN radius", soak_geometry_add_sphere(g, soak_v3(0, 0, 0), NAN, NULL), SOAK_ERR_ARG);
    soak_geometry_destroy(g);
}

/* Deterministic points/directions for the local-query test (LCG, not the
 * library's generator). */
/* Local queries (a walk inside one object) against the whole-scene queries,
 * and the isolation rule: a sphere resting on a plane or holding nothing is
 * isolated; one cut by a quad or holding another sphere is not. */
static void test_local_queries(void)
{
    soak_geometry *g = NULL;
    char err[256] = "";
    if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK)) return;
    unsigned rest = 0, cut = 0, outer = 0, inner = 0, floor_id = 0, blade = 0;
    soak_geometry_add_quad(g, soak_v3(-10, -10, 0), soak_v3(20, 0, 0), soak_v3(0, 20, 0), &floor_id);
    soak_geometry_add_sphere(g, soak_v3(0, 0, 0.6), 0.6, &rest);         /* touches the floor at one point */
    soak_geometry_add_sphere(g, soak_v3(3, 0, 0.5), 0.6, &cut);          /* floor cuts it */
    soak_geometry_add_sphere(g, soak_v3(-4, 0, 3), 1.0, &outer);         /* holds `inner` */
    soak_geometry_add_sphere(g, soak_v3(-4, 0.2, 3), 0.3, &inner);
    soak_geometry_add_quad(g, soak_v3(6, -1, 2), soak_v3(0, 2, 0), soak_v3(0, 0, 2), &blade);
    unsigned blade_sphere = 0;
    soak_geometry_add_sphere(g, soak_v3(6.5, 0, 3), 0.7, &blade_sphere); /* quad 0.5 from its centre */
    if (!check_status("commit", soak_geometry_commit(g), SOAK_OK)) {
        soak_geometry_destroy(g);
        return;
    }
    check_true("sphere resting on the floor: isolated", soak_geometry_object_isolated(g, rest));
    check_true("inner sphere: isolated", soak_geometry_object_isolated(g, inner));
    check_true("sphere cut by the floor: not isolated", !soak_geometry_object_isolated(g, cut));
    check_true("sphere holding another: not isolated", !soak_geometry_object_isolated(g, outer));
    check_true("sphere cut by a quad: not isolated", !soak_geometry_object_isolated(g, blade_sphere));
    check_true("a quad: not isolated (no closed form)", !soak_geometry_object_isolated(g, floor_id));

    /* From random points inside the resting sphere, the local closest hit and
     * occlusion equal the scene's (which refines Embree's float hit in double). */
    unsigned long long s = 12345;
    double worst_t = 0, worst_n = 0, worst_uv = 0;
    int hits_differ = 0, occl_differ = 0, nouv_differ = 0, n = 20000;
    for (int i = 0; i < n; ++i) {
        soak_vec3 d = geo_unit_dir(&s), o;
        do {
            o = soak_v3(1.2 * geo_lcg01(&s) - 0.6, 1.2 * geo_lcg01(&s) - 0.6, 1.2 * geo_lcg01(&s));
        } while (soak_v3_len(soak_v3_sub(o, soak_v3(0, 0, 0.6))) > 0.59);
        soak_ray r = geo_ray(o, d);
        soak_hit hl, hs;
        int fl = 0, fs = 0;
        soak_geometry_intersect_local(g, rest, &r, 1, &hl, &fl);
        soak_geometry_intersect(g, &r, &hs, &fs);
        if (fl != fs || (fl && (hl.object_id != hs.object_id))) {
            hits_differ++;
            continue;
        }
        worst_t = fmax(worst_t, fabs(hl.t - hs.t));
        worst_n = fmax(worst_n, soak_v3_len(soak_v3_sub(hl.ng, hs.ng)));
        worst_uv = fmax(worst_uv, fmax(fabs(hl.u - hs.u), fabs(hl.v - hs.v)));
        soak_hit hn;
        int fn = 0;
        soak_geometry_intersect_local(g, rest, &r, 0, &hn, &fn);
        if (!fn || hn.t != hl.t || soak_v3_len(soak_v3_sub(hn.ng, hl.ng)) > 1e-15 || hn.u != 0 || hn.v != 0) nouv_differ++;
        r.tfar = 1.2 * geo_lcg01(&s);
        int ol = -1, os = -1;
        soak_geometry_occluded_local(g, rest, &r, &ol);
        soak_geometry_occluded(g, &r, &os);
        /* Embree's float test may disagree within its float error of the surface. */
        if (ol != os && fabs(r.tfar - hs.t) > 1e-5) occl_differ++;
    }
    printf("  local vs scene queries inside an isolated sphere (%d rays): max |dt| %.2e, |dn| %.2e, |duv| %.2e\n", n,
           worst_t, worst_n, worst_uv);
    check_true("local hits the same object as the scene query", hits_differ == 0);
    check_true("local occlusion = scene occlusion", occl_differ == 0);
    check_true("without uv: same t and normal, u = v = 0", nouv_differ == 0);
    check_close("local t = scene t", worst_t, 0.0, 1e-9);
    check_close("local normal = scene normal", worst_n, 0.0, 1e-9);
    check_close("local uv = scene uv", worst_uv, 0.0, 1e-9);

    /* A sphere that is not isolated falls back to the scene: from inside the
     * cut sphere, straight down, the floor is hit first. */
    soak_ray down = geo_ray(soak_v3(3, 0, 0.5), soak_v3(0, 0, -1));
    soak_hit h;
    int found = 0;
    soak_geometry_intersect_local(g, cut, &down, 1, &h, &found);
    check_true("not isolated: the floor inside the sphere is found", found && h.object_id == floor_id);
    check_close("floor distance", found ? h.t : -1, 0.5, 1e-9);
    soak_ray bad = geo_ray(soak_v3(NAN, 0, 0), soak_v3(0, 0, 1));
    int occ = 0;
    check_status("NaN origin rejected (local)", soak_geometry_intersect_local(g, rest, &bad, 1, &h, &found), SOAK_ERR_ARG);
    check_status("NaN origin rejected (local occlusion)", soak_geometry_occluded_local(g, rest, &bad, &occ), SOAK_ERR_ARG);
    soak_geometry_destroy(g);
}

static void test_quad_box(void)
{
    soak_geometry *g = NULL;
    char err[256];
    if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK) || !g) return;
    unsigned q, b;
    /* Ground quad z = 0 over [-2,2]^2, normal +z. */
    check_status("add quad", soak_geometry_add_quad(g, soak_v3(-2, -2, 0), soak_v3(4, 0, 0), soak_v3(0, 4, 0), &q), SOAK_OK);
    check_status("add box", soak_geometry_add_box(g, soak_v3(0.5, 0.5, 0.25), soak_v3(1.5, 1.0, 0.75), &b), SOAK_OK);
    check_status("bad box", soak_geometry_add_box(g, soak_v3(1, 0, 0), soak_v3(0, 1, 1), NULL), SOAK_ERR_ARG);
    check_status("degenerate quad", soak_geometry_add_quad(g, soak_v3(0, 0, 0), soak_v3(1, 0, 0), soak_v3(2, 0, 0), NULL),
                 SOAK_ERR_ARG);
    check_status("commit", soak_geometry_commit(g), SOAK_OK);
    check_true("2 objects", soak_geometry_object_count(g) == 2);
    check_true("box has 12 triangles", soak_geometry_triangle_count(g, b) == 12);

    soak_hit h;
    int found;
    soak_ray r = geo_ray(soak_v3(-1, 1, 3), soak_v3(0.5, -0.25, -1));
    soak_geometry_intersect(g, &r, &h, &found);
    check_true("quad hit", found && h.object_id == q);
    if (found) {
        check_close("quad t = 3", h.t, 3.0, 1e-12);
        check_close("quad uv u = (x+2)/4", h.u, (-1 + 1.5 + 2) / 4.0, 1e-9);
        check_close("quad uv v = (y+2)/4", h.v, (1 - 0.75 + 2) / 4.0, 1e-9);
        check_close("quad normal +z", h.ng.z, 1.0, 1e-15);
    }
    /* Box top face at z = 0.75 from above; side face x = 1.5 from +x. */
    soak_ray top = geo_ray(soak_v3(1.0, 0.75, 2.0), soak_v3(0, 0, -1));
    soak_geometry_intersect(g, &top, &h, &found);
    check_true("box top hit", found && h.object_id == b);
    if (found) {
        check_close("box top t", h.t, 1.25, 1e-12);
        check_close("box top normal +z", h.ng.z, 1.0, 1e-12);
    }
    soak_ray side = geo_ray(soak_v3(5.0, 0.75, 0.5), soak_v3(-1, 0, 0));
    soak_geometry_intersect(g, &side, &h, &found);
    check_true("box side hit", found && h.object_id == b);
    if (found) {
        check_close("box side t", h.t, 3.5, 1e-12);
        check_close("box side normal +x", h.ng.x, 1.0, 1e-12);
    }
    soak_ray bottom = geo_ray(soak_v3(1.0, 0.75, 0.1), soak_v3(0, 0, 1));
    soak_geometry_intersect(g, &bottom, &h, &found);
    check_true("box bottom normal -z (outward)", found && h.ng.z < -0.999999);
    soak_vec3 lo, hi;
    check_status("bounds", soak_geometry_bounds(g, &lo, &hi), SOAK_OK);
    check_close("bounds lo x", lo.x, -2, 1e-6);
    check_close("bounds hi z", hi.z, 0.75, 1e-6);
    soak_geometry_destroy(g);
}

/* Exit distance from p (inside) along d from the axis-aligned box [lo, hi]:
 * the slab method, the independent reference for the triangle BVH. */
static double box_exit(soak_vec3 lo, soak_vec3 hi, soak_vec3 p, soak_vec3 d)
{
    double pa[3] = {p.x, p.y, p.z}, da[3] = {d.x, d.y, d.z}, la[3] = {lo.x, lo.y, lo.z}, ha[3] = {hi.x, hi.y, hi.z};
    double t = INFINITY;
    for (int a = 0; a < 3; ++a) {
        if (da[a] > 0) t = fmin(t, (ha[a] - pa[a]) / da[a]);
        if (da[a] < 0) t = fmin(t, (la[a] - pa[a]) / da[a]);
    }
    return t;
}

/* Robust traversal on: rays from inside a box aimed exactly at its 12 edges
 * (where two triangles of a face, or two faces, meet: the rays a crack lets
 * through) and 8 corners, from 64 inner points, all hit the box at the
 * slab-method distance, and a walk's query (want_uv = 0) gives the same
 * distance and face normal. Off, the hits found are as exact, but some of
 * these rays pass between the triangles (61 of 1280 with Embree 3.13.5):
 * printed, not asserted; it shows that the flag reaches Embree. */
/* 1 when n is the outward normal of a face of box lo..hi on whose plane p lies. */
static int on_face_of(soak_vec3 lo, soak_vec3 hi, soak_vec3 p, soak_vec3 n)
{
    double pp[3] = {p.x, p.y, p.z}, nn[3] = {n.x, n.y, n.z}, l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    for (int a = 0; a < 3; ++a) {
        if (fabs(fabs(nn[a]) - 1) > 1e-12) continue;
        double plane = nn[a] > 0 ? h[a] : l[a];
        return fabs(pp[a] - plane) <= 1e-9 * (1 + fabs(plane));
    }
    return 0;
}

static void test_robust_modes(void)
{
    soak_vec3 lo = soak_v3(-0.3, -0.2, 0.1), hi = soak_v3(0.7, 0.5, 0.9);
    for (int robust = 0; robust < 2; ++robust) {
        soak_geometry *g = NULL;
        char err[256];
        if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK) || !g) return;
        unsigned b;
        check_status("add box", soak_geometry_add_box(g, lo, hi, &b), SOAK_OK);
        check_status("set robust", soak_geometry_set_robust(g, robust), SOAK_OK);
        check_status("commit", soak_geometry_commit(g), SOAK_OK);
        int misses = 0, wrong = 0, local_wrong = 0;
        for (int i = 0; i < 64; ++i) {
            soak_vec3 p = soak_v3(lo.x + (hi.x - lo.x) * (0.1 + 0.8 * ((i * 37) % 64) / 63.0),
                                  lo.y + (hi.y - lo.y) * (0.1 + 0.8 * ((i * 11) % 64) / 63.0),
                                  lo.z + (hi.z - lo.z) * (0.1 + 0.8 * ((i * 23) % 64) / 63.0));
            for (int k = 0; k < 27; ++k) { /* targets: box points with each coordinate lo, mid or hi */
                int c[3] = {k % 3, (k / 3) % 3, k / 9};
                int extremes = (c[0] != 1) + (c[1] != 1) + (c[2] != 1);
                if (extremes < 2) continue; /* face centres: no edge */
                double q[3], l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
                for (int a = 0; a < 3; ++a) q[a] = c[a] == 0 ? l[a] : (c[a] == 2 ? h[a] : 0.5 * (l[a] + h[a]));
                soak_vec3 d = soak_v3_norm(soak_v3_sub(soak_v3(q[0], q[1], q[2]), p));
                double want = box_exit(lo, hi, p, d);
                soak_ray r = geo_ray(p, d);
                soak_hit h1, h2;
                int f1 = 0, f2 = 0;
                soak_geometry_intersect(g, &r, &h1, &f1);
                soak_geometry_intersect_local(g, b, &r, 0, &h2, &f2);
                if (!f1 || !f2) {
                    misses++;
                    continue;
                }
                wrong += fabs(h1.t - want) > 1e-9 * (1 + want);
                /* At an edge or corner two or three faces are hit at once:
                 * any of them is right (the local query of an isolated box
                 * is closed-form and may pick another face than Embree). */
                local_wrong += fabs(h2.t - h1.t) > 1e-12 || !on_face_of(lo, hi, h2.p, h2.ng) || h2.u != 0 ||
                               h2.v != 0 || soak_v3_dot(h2.ns, h2.ng) < 1 - 1e-12;
            }
        }
        char name[96];
        printf("  robust %d: %d of %d rays aimed at edges and corners missed\n", robust, misses, 64 * 20);
        snprintf(name, sizeof name, "robust %d: no ray from inside misses the box at an edge or corner", robust);
        if (robust) check_true(name, misses == 0);
        snprintf(name, sizeof name, "robust %d: exit distances equal the slab method's", robust);
        check_true(name, wrong == 0);
        snprintf(name, sizeof name, "robust %d: the walk's query gives the same hit without uv/shading", robust);
        check_true(name, local_wrong == 0);
        soak_geometry_destroy(g);
    }
    check_status("set robust NULL", soak_geometry_set_robust(NULL, 1), SOAK_ERR_NULL);
}

/* The walk's occlusion query inside a box mesh resting on a floor quad (the
 * box's bottom face lies on the floor): for random segments from inside, of
 * lengths up to the box size (about half of them inside the box's clear ball,
 * answered without Embree), the answer equals the independent one -- the
 * box is convex, so the segment crosses a surface iff it ends outside --
 * wherever the end is more than 1e-6 from the box's faces; and equals the
 * scene query everywhere. */
static void test_clear_ball(void)
{
    soak_geometry *g = NULL;
    char err[256];
    if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK) || !g) return;
    unsigned floor_id, box;
    soak_vec3 lo = soak_v3(-0.4, 0.1, 0), hi = soak_v3(0.6, 0.9, 0.7);
    soak_geometry_add_quad(g, soak_v3(-10, -10, 0), soak_v3(20, 0, 0), soak_v3(0, 20, 0), &floor_id);
    check_status("add box", soak_geometry_add_box(g, lo, hi, &box), SOAK_OK);
    check_status("commit", soak_geometry_commit(g), SOAK_OK);
    unsigned long long s = 777;
    int wrong = 0, differ = 0, checked = 0, n = 20000;
    for (int i = 0; i < n; ++i) {
        soak_vec3 o = soak_v3(lo.x + 1e-3 + (hi.x - lo.x - 2e-3) * geo_lcg01(&s), lo.y + 1e-3 + (hi.y - lo.y - 2e-3) * geo_lcg01(&s),
                              lo.z + 1e-3 + (hi.z - lo.z - 2e-3) * geo_lcg01(&s));
        soak_vec3 d = geo_unit_dir(&s);
        soak_ray r = {o, d, 0.0, 0.8 * geo_lcg01(&s)};
        soak_vec3 e = soak_v3_add(o, soak_v3_scale(d, r.tfar));
        double gap = fmin(fmin(fmin(fabs(e.x - lo.x), fabs(e.x - hi.x)), fmin(fabs(e.y - lo.y), fabs(e.y - hi.y))),
                          fmin(fabs(e.z - lo.z), fabs(e.z - hi.z)));
        int outside = e.x < lo.x || e.x > hi.x || e.y < lo.y || e.y > hi.y || e.z < lo.z || e.z > hi.z;
        int occ_local = -1, occ_scene = -1;
        soak_geometry_occluded_local(g, box, &r, &occ_local);
        soak_geometry_occluded(g, &r, &occ_scene);
        differ += occ_local != occ_scene;
        if (gap > 1e-6) {
            ++checked;
            wrong += occ_local != outside;
        }
    }
    printf("  clear ball: %d of %d segments checked against the box, %d wrong; %d differ from the scene query\n", checked,
           n, wrong, differ);
    check_true("box walk occlusion = ends outside the box", wrong == 0 && checked > n / 2);
    check_true("box walk occlusion = scene occlusion", differ == 0);
    soak_geometry_destroy(g);
}

/* soak_geometry_clear_distance never exceeds the distance to the nearest
 * surface (computed here from the shapes: a box's six faces, a sphere's
 * radius), is that distance for an isolated sphere and near the box's centre
 * (its inscribed ball), and is 0 outside and for a sphere the floor cuts. */
static void test_clear_distance(void)
{
    soak_geometry *g = NULL;
    char err[256];
    if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK) || !g) return;
    unsigned floor_id, box, ball, cut;
    soak_vec3 lo = soak_v3(-0.4, 0.1, 0), hi = soak_v3(0.6, 0.9, 0.7), c = soak_v3(3, 0, 0.6);
    soak_geometry_add_quad(g, soak_v3(-10, -10, 0), soak_v3(20, 0, 0), soak_v3(0, 20, 0), &floor_id);
    check_status("add box", soak_geometry_add_box(g, lo, hi, &box), SOAK_OK);
    soak_geometry_add_sphere(g, c, 0.6, &ball);                 /* rests on the floor: isolated */
    soak_geometry_add_sphere(g, soak_v3(-3, 0, 0.2), 0.5, &cut); /* the floor cuts it */
    check_status("commit", soak_geometry_commit(g), SOAK_OK);
    unsigned long long s = 4242;
    int over = 0, sphere_off = 0, n = 20000;
    for (int i = 0; i < n; ++i) {
        soak_vec3 o = soak_v3(lo.x + (hi.x - lo.x) * geo_lcg01(&s), lo.y + (hi.y - lo.y) * geo_lcg01(&s), lo.z + (hi.z - lo.z) * geo_lcg01(&s));
        double gap = fmin(fmin(fmin(o.x - lo.x, hi.x - o.x), fmin(o.y - lo.y, hi.y - o.y)), fmin(o.z - lo.z, hi.z - o.z));
        over += soak_geometry_clear_distance(g, box, o) > gap;
        soak_vec3 q;
        do {
            q = soak_v3(c.x + 1.2 * geo_lcg01(&s) - 0.6, c.y + 1.2 * geo_lcg01(&s) - 0.6, c.z + 1.2 * geo_lcg01(&s) - 0.6);
        } while (soak_v3_len(soak_v3_sub(q, c)) > 0.6);
        double depth = 0.6 - soak_v3_len(soak_v3_sub(q, c));
        double dq = soak_geometry_clear_distance(g, ball, q);
        over += dq > depth;
        sphere_off += fabs(dq - depth) > 1e-12;
    }
    printf("  clear distance: %d of %d over the true distance, sphere off its depth %d times\n", over, 2 * n, sphere_off);
    check_true("clear distance <= distance to the nearest surface", over == 0);
    check_true("isolated sphere: clear distance = depth", sphere_off == 0);
    double centre = soak_geometry_clear_distance(g, box, soak_v3(0.1, 0.5, 0.35));
    check_true("box centre: clear distance = half the box height, less the margin", centre > 0.35 - 1e-4 && centre <= 0.35);
    check_true("outside the box: 0", soak_geometry_clear_distance(g, box, soak_v3(2, 2, 2)) == 0.0);
    check_true("outside the sphere: 0", soak_geometry_clear_distance(g, ball, soak_v3(3, 0, 1.3)) == 0.0);
    check_true("sphere cut by the floor: 0", soak_geometry_clear_distance(g, cut, soak_v3(-3, 0, 0.3)) == 0.0);
    check_true("flat quad: 0", soak_geometry_clear_distance(g, floor_id, soak_v3(0, 0, 0)) == 0.0);
    check_true("NULL geometry: 0", soak_geometry_clear_distance(NULL, box, soak_v3(0.1, 0.5, 0.35)) == 0.0);
    soak_geometry_destroy(g);
}

/* A box that no other object's bounds meet (a thin sheet, a sphere beside
 * it) answers from its clear box: for random segments from inside, the
 * occlusion query equals the independent answer (convex: crossed iff the
 * end is outside, where the end is more than 1e-6 from a face) and the scene
 * query; the clear distance is the distance to the nearest face less at
 * most the margin 1e-5 (1 + max |coordinate|), never more. A box with a
 * sphere inside it gets no clear box: a segment through the sphere is
 * occluded. */
static void test_clear_box(void)
{
    soak_geometry *g = NULL;
    char err[256];
    if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK) || !g) return;
    unsigned sheet, ball, hollow, inner;
    soak_vec3 lo = soak_v3(-4, -3, -0.2), hi = soak_v3(4, 3, 0);
    check_status("add sheet", soak_geometry_add_box(g, lo, hi, &sheet), SOAK_OK);
    soak_geometry_add_sphere(g, soak_v3(0, 0, 2), 0.5, &ball);
    soak_geometry_add_box(g, soak_v3(10, 10, 0), soak_v3(12, 12, 2), &hollow);
    soak_geometry_add_sphere(g, soak_v3(11, 11, 1), 0.3, &inner);
    check_status("commit", soak_geometry_commit(g), SOAK_OK);
    unsigned long long s = 9191;
    int wrong = 0, differ = 0, checked = 0, over = 0, loose = 0, n = 20000;
    const double margin = 1e-5 * (1 + 4);
    for (int i = 0; i < n; ++i) {
        soak_vec3 o = soak_v3(lo.x + 1e-3 + (hi.x - lo.x - 2e-3) * geo_lcg01(&s), lo.y + 1e-3 + (hi.y - lo.y - 2e-3) * geo_lcg01(&s),
                              lo.z + 1e-3 + (hi.z - lo.z - 2e-3) * geo_lcg01(&s));
        double face = fmin(fmin(fmin(o.x - lo.x, hi.x - o.x), fmin(o.y - lo.y, hi.y - o.y)), fmin(o.z - lo.z, hi.z - o.z));
        double cd = soak_geometry_clear_distance(g, sheet, o);
        over += cd > face;
        loose += cd < face - margin - 1e-12;
        soak_vec3 d = geo_unit_dir(&s);
        soak_ray r = {o, d, 0.0, 0.3 * geo_lcg01(&s)};
        soak_vec3 e = soak_v3_add(o, soak_v3_scale(d, r.tfar));
        double gap = fmin(fmin(fmin(fabs(e.x - lo.x), fabs(e.x - hi.x)), fmin(fabs(e.y - lo.y), fabs(e.y - hi.y))),
                          fmin(fabs(e.z - lo.z), fabs(e.z - hi.z)));
        int outside = e.x < lo.x || e.x > hi.x || e.y < lo.y || e.y > hi.y || e.z < lo.z || e.z > hi.z;
        int occ_local = -1, occ_scene = -1;
        soak_geometry_occluded_local(g, sheet, &r, &occ_local);
        soak_geometry_occluded(g, &r, &occ_scene);
        differ += occ_local != occ_scene;
        if (gap > 1e-6) {
            ++checked;
            wrong += occ_local != outside;
        }
    }
    printf("  clear box: %d of %d segments checked, %d wrong, %d differ from the scene query; clear distance over %d, "
           "looser than the margin %d\n", checked, n, wrong, differ, over, loose);
    check_true("sheet occlusion = ends outside the box", wrong == 0 && checked > n / 2);
    check_true("sheet occlusion = scene occlusion", differ == 0);
    check_true("sheet clear distance <= distance to the nearest face", over == 0);
    check_true("sheet clear distance >= that distance less the margin", loose == 0);
    /* Rays from inside: the closed-form exit vs Embree's scene query. */
    int exit_off = 0;
    for (int i = 0; i < 5000; ++i) {
        soak_vec3 o = soak_v3(lo.x + 1e-3 + (hi.x - lo.x - 2e-3) * geo_lcg01(&s), lo.y + 1e-3 + (hi.y - lo.y - 2e-3) * geo_lcg01(&s),
                              lo.z + 1e-3 + (hi.z - lo.z - 2e-3) * geo_lcg01(&s));
        soak_ray r = {o, geo_unit_dir(&s), 0.0, INFINITY};
        soak_hit hl, hs;
        int fl = 0, fs = 0;
        soak_geometry_intersect_local(g, sheet, &r, 0, &hl, &fl);
        soak_geometry_intersect(g, &r, &hs, &fs);
        exit_off += fl != fs || !fl || hs.object_id != sheet || fabs(hl.t - hs.t) > 1e-5 * (1 + hs.t) ||
                    fabs(soak_v3_dot(hl.ng, hs.ng)) < 1 - 1e-9 || soak_v3_len(soak_v3_sub(hl.p, hs.p)) > 1e-4;
    }
    printf("  clear box: %d of 5000 exits from inside differ from the scene query\n", exit_off);
    check_true("sheet exit from inside (closed form) = scene intersection", exit_off == 0);
    soak_ray through = {soak_v3(10.5, 11, 1), soak_v3(1, 0, 0), 0.0, 1.0};
    int occ = 0;
    soak_geometry_occluded_local(g, hollow, &through, &occ);
    check_true("box with a sphere inside: a segment through the sphere is occluded", occ == 1);
    soak_geometry_destroy(g);
}

int main(void)
{
    test_sphere();
    test_quad_box();
    test_robust_modes();
    test_clear_ball();
    test_clear_distance();
    test_clear_box();
    test_local_queries();
    return check_finish();
}
