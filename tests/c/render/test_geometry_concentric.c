/* Isolation of spheres sharing one centre (issue 21, item 4): commit handles
 * a group of concentric spheres with one point query instead of one per
 * sphere (quadratic for stacked spheres); the result must equal the rule
 * "no other surface nearer the centre than the radius", here in closed
 * form: from the common centre a concentric sphere of radius r' is r' away. */
#include <stdio.h>

#include "check.h"
#include "soak/geometry.h"

int main(void)
{
    soak_geometry *g = NULL;
    char err[256] = "";
    if (!check_status("create", soak_geometry_create(&g, err, sizeof err), SOAK_OK)) return check_finish();
    unsigned twin_a, twin_b, big, small, cut_big, cut_small, floor_id, lone;
    soak_vec3 c1 = soak_v3(0, 0, 5), c2 = soak_v3(10, 0, 5), c3 = soak_v3(20, 0, 0.5);
    soak_geometry_add_sphere(g, c1, 1.0, &twin_a); /* identical twins: each 1.0 from the other's centre */
    soak_geometry_add_sphere(g, c1, 1.0, &twin_b);
    soak_geometry_add_sphere(g, c2, 1.0, &big); /* holds `small`: 0.5 from its centre */
    soak_geometry_add_sphere(g, c2, 0.5, &small); /* `big` is 1.0 away: isolated */
    soak_geometry_add_quad(g, soak_v3(15, -5, 0), soak_v3(10, 0, 0), soak_v3(0, 10, 0), &floor_id);
    soak_geometry_add_sphere(g, c3, 1.0, &cut_big);   /* the floor 0.5 from the centre cuts it */
    soak_geometry_add_sphere(g, c3, 0.4, &cut_small); /* floor 0.5 and cut_big 1.0 away: isolated */
    soak_geometry_add_sphere(g, soak_v3(-10, 0, 5), 1.0, &lone);
    /* a large stack: 3000 identical spheres and one smaller inside */
    unsigned first = 0, last = 0, inner = 0;
    for (int i = 0; i < 3000; ++i) soak_geometry_add_sphere(g, soak_v3(0, 20, 5), 2.0, i ? &last : &first);
    soak_geometry_add_sphere(g, soak_v3(0, 20, 5), 1.5, &inner);
    if (!check_status("commit", soak_geometry_commit(g), SOAK_OK)) {
        soak_geometry_destroy(g);
        return check_finish();
    }
    check_true("identical twins: isolated (the other is exactly one radius away)",
               soak_geometry_object_isolated(g, twin_a) && soak_geometry_object_isolated(g, twin_b));
    check_true("concentric: the outer holds the inner, not isolated", !soak_geometry_object_isolated(g, big));
    check_true("concentric: the inner is isolated", soak_geometry_object_isolated(g, small));
    check_true("concentric, floor cuts the outer: not isolated", !soak_geometry_object_isolated(g, cut_big));
    check_true("concentric, floor beyond the inner: isolated", soak_geometry_object_isolated(g, cut_small));
    check_true("a lone sphere: isolated", soak_geometry_object_isolated(g, lone));
    check_true("stack of 3000 with a smaller one inside: not isolated",
               !soak_geometry_object_isolated(g, first) && !soak_geometry_object_isolated(g, last));
    check_true("the smaller one inside the stack: isolated", soak_geometry_object_isolated(g, inner));
    soak_geometry_destroy(g);
    return check_finish();
}
