/* Wetness -> parameter mapping; the formula chain is documented step by
 * step in soak/wetness.h (steps 1-6 below refer to it). */
#include "soak/wetness.h"

#include <math.h>
#include <string.h>

#include "soak/film.h"
#include "soak/fresnel.h"
#include "soak/porous.h"
#include "soak/vdhulst.h"

static double lerp(double a, double b, double t) { return a + (b - a) * t; }
static double clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

soak_wet_input soak_wet_input_steady(const soak_preset *preset, double wetness)
{
    soak_wet_input in;
    in.wetness = wetness;
    in.time = 1.0;
    in.t0 = 0.0;
    in.t_fill = 0.0;
    in.film_thickness_m = preset ? preset->film_thickness_m : 0.0;
    return in;
}

static soak_status validate(const soak_preset *p, const soak_liquid *l, const soak_wet_input *in)
{
    if (!p || !l || !in) return SOAK_ERR_NULL;
    if (!soak_in_range(in->wetness, 0.0, 1.0) || !soak_in_range(in->time, -SOAK_WET_TIME_MAX, SOAK_WET_TIME_MAX) ||
        !soak_in_range(in->t0, -SOAK_WET_TIME_MAX, SOAK_WET_TIME_MAX) ||
        !soak_in_range(in->t_fill, 0.0, SOAK_WET_TIME_MAX) ||
        !soak_in_range(in->film_thickness_m, 0.0, SOAK_WET_FILM_MAX_M))
        return SOAK_ERR_ARG;
    /* The preset and liquid come from the validated loader, but a caller may
     * build one by hand: check what the formulas rely on. */
    if ((int)p->kind < 0 || (int)p->kind > SOAK_KIND_THIN_SHEET) return SOAK_ERR_ARG;
    /* Fields a kind does not read (a conductor's phase and medium, a
     * non-porous kind's porosity) must still be numbers: NaN is a caller's
     * error wherever it sits. */
    const double any[] = {p->porosity, p->phase_dry.g1, p->phase_dry.g2, p->phase_dry.w, p->phase_wet.g1,
                          p->phase_wet.g2, p->phase_wet.w, p->sigma_t_per_m.r, p->sigma_t_per_m.g, p->sigma_t_per_m.b};
    for (size_t i = 0; i < sizeof any / sizeof any[0]; ++i)
        if (!soak_is_finite(any[i])) return SOAK_ERR_ARG;
    if (!soak_in_range(l->ior, 1.0, 3.0)) return SOAK_ERR_ARG;
    if (!soak_in_range(p->ggx_alpha_dry, 1e-4, 1.0) || !soak_in_range(p->ggx_alpha_wet, 1e-4, 1.0)) return SOAK_ERR_ARG;
    for (int i = 0; i < 3; ++i) {
        if (!soak_in_range(soak_rgb_at(p->albedo, i), 0.0, 1.0) ||
            !soak_in_range(soak_rgb_at(l->sigma_a_per_m, i), 0.0, SOAK_LIQUID_SIGMA_MAX_PER_M) ||
            !soak_in_range(soak_rgb_at(l->sigma_s_per_m, i), 0.0, SOAK_LIQUID_SIGMA_MAX_PER_M))
            return SOAK_ERR_ARG;
    }
    if (p->kind == SOAK_KIND_CONDUCTOR) {
        for (int i = 0; i < 3; ++i)
            if (!soak_in_range(soak_rgb_at(p->ior_n, i), SOAK_ETA_MIN, 100.0) ||
                !soak_in_range(soak_rgb_at(p->ior_k, i), 0.0, 100.0))
                return SOAK_ERR_ARG;
        return SOAK_OK;
    }
    if (soak_hg2_validate(&p->phase_dry) != SOAK_OK || soak_hg2_validate(&p->phase_wet) != SOAK_OK)
        return SOAK_ERR_ARG;
    if (soak_material_kind_porous(p->kind) && !soak_in_range(p->porosity, 1e-3, 0.95)) return SOAK_ERR_ARG;
    for (int i = 0; i < 3; ++i)
        if (!soak_in_range(soak_rgb_at(p->omega_dry, i), 0.0, 1.0) ||
            !soak_in_range(soak_rgb_at(p->sigma_t_per_m, i), 0.0, SOAK_SIGMA_T_MAX_PER_M))
            return SOAK_ERR_ARG;
    return SOAK_OK;
}


/* Step 5 for conductors: normal-incidence incoherent film over a metal. */
static double conductor_film(double n, double k, double n_liq, double two_pass)
{
    double r12 = 0.0, r23 = 0.0;
    soak_fresnel_r0(n_liq, 0.0, &r12);
    soak_fresnel_r0(n / n_liq, k / n_liq, &r23);
    double t12 = 1.0 - r12;
    return t12 * t12 * r23 * two_pass / (1.0 - r12 * r23 * two_pass);
}

/* Step 5 for dielectrics: the diffuse light leaving through a film over a
 * Lambertian base, T(A) - T(0), and the film's own specular part T(0), for
 * uniform diffuse light (cos_i < 0) or collimated light at cos_i. */
static soak_status film_ctx_parts(const soak_film_ctx *ctx, double base, double cos_i, double *diffuse,
                                  double *specular)
{
    double total = 0.0;
    soak_status st;
    if (cos_i < 0.0) {
        st = soak_film_ctx_albedo_diffuse(ctx, base, &total);
        if (st == SOAK_OK) st = soak_film_ctx_albedo_diffuse(ctx, 0.0, specular);
    } else {
        st = soak_film_ctx_albedo_dir(ctx, base, cos_i, &total);
        if (st == SOAK_OK) st = soak_film_ctx_albedo_dir(ctx, 0.0, cos_i, specular);
    }
    if (st != SOAK_OK) return st;
    *diffuse = total - *specular;
    if (*diffuse < 0.0) *diffuse = 0.0; /* rounding when base = 0 */
    return SOAK_OK;
}

/* Step 5: one Lekner-Dorf interface wherever liquid meets air -- the pore
 * water's surface (area fraction porosity f, zero thickness) and the film
 * (coverage c, which replaces it: one interface, one TIR). Reads the
 * steps 1-4 fields of o; cos_i < 0 is uniform diffuse light. */
static soak_status interface_step(const soak_preset *p, const soak_liquid *l, const soak_wet_params *o,
                                  double cos_i, soak_rgb *albedo, soak_rgb *albedo_total, soak_rgb *albedo_film)
{
    const int conductor = p->kind == SOAK_KIND_CONDUCTOR;
    soak_film film = {l->ior, 0.0, o->film_thickness_m};
    const soak_film pores = {l->ior, 0.0, 0.0};
    const double pore_area = soak_material_kind_porous(p->kind) ? p->porosity * o->fill : 0.0;
    /* The pores' interface is the same in every channel: one set-up (its
     * Fresnel average was most of soak export's time, computed per channel). */
    soak_film_ctx pore_ctx = {0};
    if (!conductor && pore_area > 0.0) {
        soak_status st = soak_film_setup(&pores, &pore_ctx);
        if (st != SOAK_OK) return st;
    }
    for (int i = 0; i < 3; ++i) {
        double base = soak_rgb_at(o->albedo_subsurface, i);
        double diffuse, specular;
        double open = base, open_total = base; /* the part not under the film */
        if (conductor) {
            /* normal-incidence model whatever the light (wetness.h step 5) */
            double two_pass = exp(-2.0 * soak_rgb_at(o->film_absorption_per_m, i) * o->film_thickness_m);
            soak_fresnel_r0(l->ior, 0.0, &specular);
            diffuse = conductor_film(soak_rgb_at(p->ior_n, i), soak_rgb_at(p->ior_k, i), l->ior, two_pass);
        } else {
            film.alpha = soak_rgb_at(o->film_absorption_per_m, i);
            soak_film_ctx film_ctx; /* one quadrature set-up for both evaluations */
            soak_status st = soak_film_setup(&film, &film_ctx);
            if (st == SOAK_OK) st = film_ctx_parts(&film_ctx, base, cos_i, &diffuse, &specular);
            if (st == SOAK_OK && pore_area > 0.0) {
                double pore_diffuse = 0.0, pore_specular = 0.0;
                st = film_ctx_parts(&pore_ctx, base, cos_i, &pore_diffuse, &pore_specular);
                open = lerp(base, pore_diffuse, pore_area);
                open_total = lerp(base, pore_diffuse + pore_specular, pore_area);
            }
            if (st != SOAK_OK) return st;
        }
        double c = o->film_coverage;
        if (albedo_film) soak_rgb_set(albedo_film, i, diffuse);
        soak_rgb_set(albedo, i, c > 0.0 ? lerp(open, diffuse, c) : open);
        soak_rgb_set(albedo_total, i, c > 0.0 ? lerp(open_total, diffuse + specular, c) : open_total);
    }
    return SOAK_OK;
}

soak_status soak_wetness_eval(const soak_preset *p, const soak_liquid *l, const soak_wet_input *in,
                              soak_wet_params *out)
{
    if (!out) return SOAK_ERR_NULL;
    soak_status st = validate(p, l, in);
    if (st != SOAK_OK) return st;
    const int conductor = p->kind == SOAK_KIND_CONDUCTOR;
    const int porous = soak_material_kind_porous(p->kind);

    soak_wet_params o;
    memset(&o, 0, sizeof o);
    o.wetness = in->wetness;
    /* Step 1: the one schedule (soak/porous.h); in range after validate(). */
    st = soak_fill_fraction(in->time, in->t0, in->t_fill, &o.progress);
    if (st != SOAK_OK) return st;
    o.liquid = in->wetness * o.progress;

    /* Step 2. */
    o.saturation = porous ? p->porosity : 0.0;
    o.fill = porous ? clamp01(o.liquid / o.saturation) : 0.0;
    o.film_coverage = clamp01((o.liquid - o.saturation) / (1.0 - o.saturation));
    o.film = o.film_coverage > 0.0;
    o.film_thickness_m = in->film_thickness_m;
    o.film_ior = l->ior;
    o.film_absorption_per_m = l->sigma_a_per_m;

    /* Steps 3-4. */
    if (!conductor) {
        o.phase.g1 = lerp(p->phase_dry.g1, p->phase_wet.g1, o.fill);
        o.phase.g2 = lerp(p->phase_dry.g2, p->phase_wet.g2, o.fill);
        o.phase.w = lerp(p->phase_dry.w, p->phase_wet.w, o.fill);
        o.mean_cosine = soak_hg2_mean_cosine(&o.phase);
        double liquid_volume = porous ? p->porosity * o.fill : 0.0;
        for (int i = 0; i < 3; ++i) {
            double omega_dry = soak_rgb_at(p->omega_dry, i), sigma_t = soak_rgb_at(p->sigma_t_per_m, i);
            double ss = omega_dry * sigma_t + liquid_volume * soak_rgb_at(l->sigma_s_per_m, i);
            double sa = (1.0 - omega_dry) * sigma_t + liquid_volume * soak_rgb_at(l->sigma_a_per_m, i);
            /* At f = 0 use omega_dry itself so that w = 0 reproduces the dry
             * albedo bit for bit (ss / (ss + sa) could differ in the last ulp). */
            double omega = liquid_volume > 0.0 && ss + sa > 0.0 ? ss / (ss + sa) : omega_dry;
            double r = soak_rgb_at(p->albedo, i);
            if (o.fill > 0.0) {
                st = soak_vdhulst_albedo(clamp01(omega), o.mean_cosine, &r);
                if (st != SOAK_OK) return st;
            }
            soak_rgb_set(&o.omega, i, omega);
            soak_rgb_set(&o.sigma_s_per_m, i, ss);
            soak_rgb_set(&o.sigma_a_per_m, i, sa);
            soak_rgb_set(&o.albedo_subsurface, i, r);
        }
    } else {
        o.albedo_subsurface = p->albedo;
    }

    /* Step 5. */
    st = interface_step(p, l, &o, -1.0, &o.albedo, &o.albedo_total, &o.albedo_film);
    if (st != SOAK_OK) return st;

    /* Step 6. */
    o.ggx_alpha = lerp(p->ggx_alpha_dry, p->ggx_alpha_wet, o.fill);
    o.specular_weight = 1.0 - (porous ? p->porosity : 0.0);
    o.water_specular_weight = porous ? p->porosity * o.fill : 0.0;

    for (int i = 0; i < 3; ++i) {
        double v[] = {soak_rgb_at(o.albedo, i), soak_rgb_at(o.albedo_total, i), soak_rgb_at(o.albedo_film, i),
                      soak_rgb_at(o.albedo_subsurface, i), soak_rgb_at(o.sigma_s_per_m, i), soak_rgb_at(o.sigma_a_per_m, i),
                      soak_rgb_at(o.omega, i)};
        for (size_t j = 0; j < sizeof v / sizeof v[0]; ++j)
            if (!soak_is_finite(v[j])) return SOAK_ERR_NUMERIC;
    }
    if (!soak_is_finite(o.mean_cosine) || !soak_is_finite(o.ggx_alpha)) return SOAK_ERR_NUMERIC;
    *out = o;
    return SOAK_OK;
}

soak_status soak_wetness_albedo_sun(const soak_preset *p, const soak_liquid *l, const soak_wet_params *w,
                                    double cos_i, soak_rgb *albedo, soak_rgb *albedo_total)
{
    if (!p || !l || !w || !albedo || !albedo_total) return SOAK_ERR_NULL;
    if (!soak_in_range(cos_i, 0.0, 1.0) || !soak_in_range(w->fill, 0.0, 1.0) ||
        !soak_in_range(w->film_coverage, 0.0, 1.0) || !soak_in_range(w->film_thickness_m, 0.0, SOAK_WET_FILM_MAX_M))
        return SOAK_ERR_ARG;
    for (int i = 0; i < 3; ++i)
        if (!soak_in_range(soak_rgb_at(w->albedo_subsurface, i), 0.0, 1.0) ||
            !soak_in_range(soak_rgb_at(w->film_absorption_per_m, i), 0.0, SOAK_LIQUID_SIGMA_MAX_PER_M))
            return SOAK_ERR_ARG;
    soak_rgb a, t;
    soak_status st = interface_step(p, l, w, cos_i, &a, &t, NULL);
    if (st != SOAK_OK) return st;
    for (int i = 0; i < 3; ++i)
        if (!soak_is_finite(soak_rgb_at(a, i)) || !soak_is_finite(soak_rgb_at(t, i))) return SOAK_ERR_NUMERIC;
    *albedo = a;
    *albedo_total = t;
    return SOAK_OK;
}

soak_status soak_wetness_view_factor(const soak_preset *p, const soak_liquid *l, const soak_wet_params *w,
                                     double cos_o, soak_rgb *factor)
{
    if (!factor) return SOAK_ERR_NULL;
    soak_rgb dir, dir_total;
    soak_status st = soak_wetness_albedo_sun(p, l, w, cos_o, &dir, &dir_total);
    if (st != SOAK_OK) return st;
    for (int i = 0; i < 3; ++i) {
        const double hemi = soak_rgb_at(w->albedo, i);
        /* below 1e-12 the ratio is rounding noise; a black colour stays black whatever the factor */
        soak_rgb_set(factor, i, hemi > 1e-12 ? soak_rgb_at(dir, i) / hemi : 1.0);
    }
    return SOAK_OK;
}

soak_status soak_wetness_measured_ratio(const soak_preset *p, const soak_liquid *l, double wetness, double *ratio)
{
    if (!p || !l || !ratio) return SOAK_ERR_NULL;
    if (!p->has_measured || !soak_in_range(wetness, 0.0, 1.0)) return SOAK_ERR_ARG;
    soak_preset q = *p;
    const double dry = p->measured_dry_albedo;
    q.albedo = soak_rgb3(dry, dry, dry);
    soak_status st = soak_preset_derive(&q);
    soak_wet_input in = soak_wet_input_steady(&q, wetness);
    soak_wet_params o;
    if (st == SOAK_OK) st = soak_wetness_eval(&q, l, &in, &o);
    soak_rgb a = o.albedo, t = o.albedo_total;
    const double z = p->measured_sun_zenith_deg;
    if (st == SOAK_OK && z >= 0.0)
        st = soak_wetness_albedo_sun(&q, l, &o, z >= 90.0 ? 0.0 : cos(z * (SOAK_PI / 180.0)), &a, &t);
    if (st != SOAK_OK) return st;
    *ratio = (p->measured_total ? t.g : a.g) / dry;
    return SOAK_OK;
}

double soak_wet_interface_area(const soak_wet_params *w)
{
    if (!w) return 0.0;
    double c = w->film_coverage, a = c + (1.0 - c) * w->water_specular_weight;
    return soak_in_range(a, 0.0, 1.0) ? a : (a > 1.0 ? 1.0 : 0.0);
}

soak_status soak_wetness_table(const soak_preset *p, const soak_liquid *l, int n, double film_thickness_m,
                               soak_wet_params *rows)
{
    if (!p || !l || !rows) return SOAK_ERR_NULL;
    if (n < 2 || n > SOAK_WET_TABLE_MAX) return SOAK_ERR_ARG;
    if (!soak_is_finite(film_thickness_m) || film_thickness_m > SOAK_WET_FILM_MAX_M) return SOAK_ERR_ARG;
    for (int i = 0; i < n; ++i) {
        soak_wet_input in = soak_wet_input_steady(p, (double)i / (double)(n - 1));
        if (film_thickness_m >= 0.0) in.film_thickness_m = film_thickness_m;
        soak_status st = soak_wetness_eval(p, l, &in, &rows[i]);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}
