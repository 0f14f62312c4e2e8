/* The air | film | material layer stack that surfaces, media and photons
 * all cross (soak/jensen.h's model, sampled): Fresnel at one interface, a
 * stochastic crossing of the whole stack, and Snell's direction after it. */
#include <math.h>

#include "render_stack.h"
#include "soak/fresnel.h"

static double pow_k(double F, double k) { return k == 1.0 ? F : pow(F, k); }

double rt_fresnel(double cos_i, double eta, double *cos_t)
{
    double ct = 0;
    if (eta == 1.0) {
        if (cos_t) *cos_t = cos_i;
        return 0.0;
    }
    double F = soak_fresnel_dielectric_raw(fmin(1.0, fmax(0.0, cos_i)), eta, &ct);
    if (cos_t) *cos_t = ct;
    return F;
}

/* Crosses the layer stack. p = n sin(theta), the Snell invariant. start_low:
 * the path starts in the material going up (else in air going down).
 * Returns 1 if it ends in the material (going down), 0 in air (going up).
 * Multiplies *beta by the film absorption. The radiance factors of the
 * crossings multiply to 1/n3^2 (air -> material), n3^2 (material -> air) or
 * 1 (back to the starting side) whatever happens in the film, so they are
 * not applied here: the walk carries beta without the 1/n3^2 and the
 * estimates gathered inside multiply by it instead (add_delta_light and
 * caustic_light in render_medium.c). That keeps the roulette from killing
 * paths for a factor that is undone when they leave. */
rt_stack rt_wet_stack(rt_thread *t, const soak_material *m, double wet)
{
    double u = rt_rand(t), p_film = wet * m->film_coverage;
    rt_stack s = {u < p_film ? m->film_ior : 1.0, m->medium.ior, m->film_k, m->film_absorption,
                  u < p_film * (1.0 - m->film_pore_share) ? m->film_thickness : 0.0};
    return s;
}

int rt_cross_stack(rt_thread *t, const rt_stack *s, double p, int start_low, soak_rgb *beta)
{
    /* an index-matched film still absorbs over its thickness (as the light
     * estimate's film_absorbed counts it) */
    int film = s->n2 != 1.0 || (s->h > 0 && rgb_max(s->alpha) > 0);
    double cos_film = film ? sqrt(fmax(0.0, 1 - (p / s->n2) * (p / s->n2))) : 0;
    int absorbing = film && s->h > 0 && rgb_max(s->alpha) > 0;
    /* state: 0 at the top interface going down (from air) or up (from film);
     * we track layer (0 air, 1 film, 2 material) and direction up/down. */
    int layer = start_low ? 2 : 0, up = start_low;
    for (int i = 0; i < RT_FILM_MAX_BOUNCES; ++i) {
        if (layer == 0) { /* in air going down onto the film top (or the material if no film) */
            if (film) {
                double cos1 = sqrt(fmax(0.0, 1 - p * p));
                if (rt_rand(t) < rt_fresnel(cos1, s->n2, NULL)) return 0;
                if (absorbing) *beta = soak_rgb_mul(*beta, rgb_exp(s->alpha, s->h / cos_film));
                layer = 1;
                up = 0;
            } else {
                double cos1 = sqrt(fmax(0.0, 1 - p * p));
                if (rt_rand(t) < pow_k(rt_fresnel(cos1, s->n3, NULL), s->k)) return 0;
                return 1;
            }
        } else if (layer == 2) { /* in the material going up */
            double cos3 = sqrt(fmax(0.0, 1 - (p / s->n3) * (p / s->n3)));
            double nt = film ? s->n2 : 1.0;
            double F = p >= nt ? 1.0 : rt_fresnel(cos3, nt / s->n3, NULL);
            F = pow_k(F, s->k);
            if (rt_rand(t) < F) return 1;
            if (!film) return 0;
            if (absorbing) *beta = soak_rgb_mul(*beta, rgb_exp(s->alpha, s->h / cos_film));
            layer = 1;
            up = 1;
        } else if (up) { /* in the film going up to the air */
            double F = p >= 1.0 ? 1.0 : rt_fresnel(cos_film, 1.0 / s->n2, NULL);
            if (rt_rand(t) >= F) return 0;
            if (absorbing) *beta = soak_rgb_mul(*beta, rgb_exp(s->alpha, s->h / cos_film));
            up = 0;
        } else { /* in the film going down to the material */
            double F = pow_k(rt_fresnel(cos_film, s->n3 / s->n2, NULL), s->k);
            if (rt_rand(t) >= F) return 1;
            if (absorbing) *beta = soak_rgb_mul(*beta, rgb_exp(s->alpha, s->h / cos_film));
            up = 1;
        }
    }
    t->n.capped++;
    *beta = soak_rgb3(0, 0, 0);
    return 1;
}

/* Direction after crossing: tangential unit tdir, Snell invariant p, in
 * medium of index n, along +n_out (up) or -n_out (down). */
soak_vec3 rt_snell_dir(soak_vec3 tdir, soak_vec3 n_out, double p, double n, int up)
{
    double s = p / n, c = sqrt(fmax(0.0, 1 - s * s));
    return soak_v3_norm(soak_v3_add(soak_v3_scale(tdir, s), soak_v3_scale(n_out, up ? c : -c)));
}

