/* Smooth dielectric boundary (glass, a liquid body): a Fresnel choice
 * between mirror reflection and refraction, from either side. Beer-Lambert
 * absorption inside is the caller's (it depends on the distance travelled). */
#include "bsdf_internal.h"

static soak_status glass_setup(soak_bsdf *b)
{
    if (!soak_in_range(b->d.ior, 1, 3)) return SOAK_ERR_ARG;
    b->flags = SOAK_BSDF_DELTA | SOAK_BSDF_TRANSMIT;
    return SOAK_OK;
}

/* wo.z > 0: arriving from outside (index 1 -> ior); wo.z < 0: from inside. */
static soak_status glass_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    *ok = 1;
    int entering = wo.z > 0;
    double eta = entering ? b->d.ior : 1.0 / b->d.ior, side = entering ? 1.0 : -1.0;
    double cos_i = fabs(wo.z), cos_t;
    double F = bsdf_fresnel(cos_i, eta, &cos_t);
    s->delta = 1;
    s->pdf = 0;
    if (u[0] < F) {
        s->wi = bsdf_mirror(wo);
        s->weight = soak_rgb3(1, 1, 1);
        return SOAK_OK;
    }
    /* Refraction: tangential part / eta, normal part cos_t on the far side;
     * radiance gets 1/eta^2 (L / n^2 is invariant). */
    s->wi = soak_v3_norm(soak_v3(-wo.x / eta, -wo.y / eta, -side * cos_t));
    s->weight = soak_rgb3(1 / (eta * eta), 1 / (eta * eta), 1 / (eta * eta));
    s->eta = eta;
    return SOAK_OK;
}

/* Both lobes are delta: nothing for eval or pdf. */
static soak_status glass_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    (void)b, (void)wi, (void)wo;
    *f = soak_rgb3(0, 0, 0);
    *pdf = 0;
    return SOAK_OK;
}

static double glass_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    (void)b, (void)wi, (void)wo;
    return 0;
}

const soak_bsdf_ops bsdf_glass_ops = {glass_setup, glass_eval, glass_pdf, glass_sample, NULL};
