/* A surface point whose wetness lies strictly between 0 and 1 shows a
 * mixture of the dry and wet BSDFs (and the pore BSDF) weighted by their
 * shares, as Cycles' mix closure does. Choosing one by its share and
 * shading with it alone is unbiased but adds the spread between the
 * components to every light estimate (the puddles' soft edges); here light
 * estimates evaluate the whole mixture f = sum_i w_i f_i, and a continuation
 * still samples one component by its share, weighted f cos / pdf with the
 * mixture's pdf = sum_i w_i pdf_i (Veach 1997 sec. 9.2.2's one-sample model:
 * the balance heuristic over the components). A delta lobe has no density:
 * its weight is the component's own (reflectance w_i R over probability w_i
 * P). Closed-form components only: a traced film's eval is an estimate and
 * a ratio of estimates would be biased, glass transmits; those keep the
 * one-component choice (rt_mix_can). */
#include "render_mix.h"

int rt_mix_can(const rt_bsdf_mix *m)
{
    if (m->n < 2) return 0;
    for (int i = 0; i < m->n; ++i)
        if (soak_bsdf_get_flags(m->b[i]) & (SOAK_BSDF_TRANSMIT | SOAK_BSDF_WALK)) return 0;
    return 1;
}

int rt_mix_flags(const rt_bsdf_mix *m)
{
    if (m->n == 1) return m->b[0]->flags;
    int f = 0;
    for (int i = 0; i < m->n; ++i) f |= soak_bsdf_get_flags(m->b[i]);
    return f;
}

soak_status rt_mix_eval(const rt_bsdf_mix *m, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    if (m->n == 1) return soak_bsdf_eval(m->b[0], wi, wo, f, pdf);
    soak_rgb fs = soak_rgb3(0, 0, 0);
    double ps = 0;
    for (int i = 0; i < m->n; ++i) {
        soak_rgb fi;
        double pi;
        soak_status st = soak_bsdf_eval(m->b[i], wi, wo, &fi, &pi);
        if (st != SOAK_OK) return st;
        fs = soak_rgb_add(fs, soak_rgb_scale(fi, m->w[i]));
        ps += m->w[i] * pi;
    }
    *f = fs;
    *pdf = ps;
    return SOAK_OK;
}

/* Replaces a non-delta sample's weight and pdf (drawn from one component)
 * by the mixture's; 0 when the mixture gives no density there. */
int rt_mix_reweight(const rt_bsdf_mix *m, soak_vec3 wo, soak_bsdf_sample *s)
{
    if (s->delta) return 1;
    soak_rgb f;
    double pdf;
    if (rt_mix_eval(m, s->wi, wo, &f, &pdf) != SOAK_OK || !(pdf > 0)) return 0;
    s->weight = soak_rgb_scale(f, s->wi.z / pdf);
    s->pdf = pdf;
    return 1;
}
