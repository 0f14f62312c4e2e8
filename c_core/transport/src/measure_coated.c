/* soak measure --config coated: a rough dielectric interface over a
 * Lambertian base, under an optional smooth liquid film, traced photon by
 * photon (soak/measure.h). Nothing here sums a series or uses a tabulated
 * albedo: the interface is a GGX microsurface whose facet is drawn for each
 * crossing (visible normals, Heitz 2018), the facet's Fresnel choice is
 * played, and the reflected photon survives the microsurface's masking with
 * probability G2 / G1 (Heitz 2014: the single-scattering lobe; what it loses
 * goes on into the body, as the renderer's COATED BSDF assumes). The
 * interface is first-surface: the same facets, with the same Fresnel
 * choice, meet light leaving the body from below (no refraction into a bulk
 * index). The film: Fresnel at its top (total internal reflection at its
 * underside), Beer-Lambert absorption along the slanted legs. */
#include <math.h>

#include "measure_internal.h"
#include "soak/fresnel.h"
#include "soak/ggx.h"

/* One meeting with the interface for a photon travelling against w (w
 * points away from the interface on the photon's side, w.z > 0 in that
 * side's frame): 1 when the facets reflect it back to that side, along *r. */
static int interface_reflects(const soak_measure_setup *s, soak_vec3 w, soak_rng *rng, soak_vec3 *r_out)
{
    if (!(soak_rng_uniform(rng) < s->coat_weight)) return 0;
    soak_vec3 h;
    double pdf_h;
    double u1 = soak_rng_uniform(rng), u2 = soak_rng_uniform(rng);
    if (soak_ggx_sample_vndf(s->coat_alpha, w, u1, u2, &h, &pdf_h) != SOAK_OK) return 0;
    double wh = soak_v3_dot(w, h), cos_t;
    if (!(wh > 0)) return 0;
    double F = soak_fresnel_dielectric_raw(wh, s->coat_ior / s->ior, &cos_t);
    if (!(soak_rng_uniform(rng) < F)) return 0;
    soak_vec3 r = soak_v3_sub(soak_v3_scale(h, 2 * wh), w);
    if (!(r.z > 0)) return 0;
    double keep = soak_ggx_G2_raw(s->coat_alpha, r, w) / soak_ggx_G1_raw(s->coat_alpha, w);
    *r_out = soak_v3_norm(r);
    return soak_rng_uniform(rng) < keep;
}

static double leg(const soak_measure_setup *s, double cos)
{
    return s->film_alpha > 0 && s->film_thickness > 0 ? exp(-s->film_alpha * s->film_thickness / cos) : 1.0;
}

/* The photon leaves the interface upwards along up (in the film): through
 * the film's underside, or back down. 1: left into the air. */
static int film_exit(const soak_measure_setup *s, soak_vec3 *up, double *w, soak_rng *rng)
{
    if (s->ior == 1.0) return 1;
    *w *= leg(s, up->z);
    double cos_t;
    double F = soak_fresnel_dielectric_raw(up->z, 1.0 / s->ior, &cos_t);
    if (soak_rng_uniform(rng) < F) {
        *w *= leg(s, up->z); /* back down to the interface */
        return 0;
    }
    return 1;
}

soak_status measure_coated_path(const soak_measure_setup *s, soak_vec3 d, soak_rng *rng, double *r_out, long *events,
                                int *capped)
{
    double w = 1.0, cos_t;
    *r_out = 0.0;
    *events = 0;
    *capped = 0;
    if (s->ior != 1.0) {
        if (soak_rng_uniform(rng) < soak_fresnel_dielectric_raw(-d.z, s->ior, &cos_t)) {
            *r_out = 1.0; /* the film's mirror */
            return SOAK_OK;
        }
        d = soak_v3_norm(soak_v3(d.x / s->ior, d.y / s->ior, -cos_t));
        w *= leg(s, cos_t);
    }
    soak_vec3 back = soak_v3_scale(d, -1.0); /* against the photon's way down */
    for (long ev = 0; ev < s->max_events; ++ev) {
        *events = ev + 1;
        soak_vec3 up;
        if (!interface_reflects(s, back, rng, &up)) {
            /* into the body, a Lambertian reflector of albedo base_albedo
             * (roulette), until the interface lets it out upwards; from
             * below its azimuth does not matter, only its cosine */
            int out = 0;
            for (; !out && ev < s->max_events; ++ev) {
                if (!(soak_rng_uniform(rng) < s->base_albedo)) return SOAK_OK;
                up = soak_cosine_hemisphere(soak_rng_uniform(rng), soak_rng_uniform(rng));
                soak_vec3 ignored;
                out = !interface_reflects(s, up, rng, &ignored);
            }
            if (!out) break;
        }
        *events = ev + 1;
        if (film_exit(s, &up, &w, rng)) {
            *r_out = w;
            return SOAK_OK;
        }
        back = soak_v3(-up.x, -up.y, up.z); /* reflected at the underside, down again */
    }
    *capped = 1;
    return SOAK_OK;
}
