/* Stability sweeps of the layered models: porous, porous GGX, Weidlich-Wilkie
 * (issue 20; driver: test_stability.c). */
#include "stability_args.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "soak/fresnel.h"
#include "soak/ggx.h"
#include "soak/models.h"
#include "soak/porous.h"
#include "soak/ww.h"
#include "check.h"

/* ---- porous.h ----------------------------------------------------------- */

static soak_porous_params pick_porous(soak_rng *r, double pb, int *v)
{
    soak_porous_params p;
    p.kd = arg(r, 0.0, 1.0, pb, v);
    p.ks = arg(r, 0.0, 1.0, pb, v);
    if (*v && p.ks + p.kd > 1.0 && uni(r) < 0.7) p.ks = 1.0 - p.kd; /* mostly keep k_s + k_d <= 1 */
    if (!(p.ks + p.kd <= 1.0)) *v = 0;
    p.m = arg(r, 0.0, SOAK_POROUS_M_MAX, pb, v);
    p.spec_power = arg(r, 0.0, SOAK_POROUS_POWER_MAX, pb, v);
    p.porosity = arg(r, 0.0, 1.0, pb, v);
    p.sp = arg(r, 0.0, SOAK_POROUS_SP_MAX, pb, v);
    p.ks_water = arg(r, 0.0, SOAK_POROUS_KS_WATER_MAX, pb, v);
    p.water_power = arg(r, 0.0, SOAK_POROUS_POWER_MAX, pb, v);
    p.norm = uni(r) < 0.8 ? SOAK_BLINN_NORM_ENERGY : SOAK_BLINN_NORM_SEED001;
    if (uni(r) < pb) {
        p.norm = (soak_blinn_norm)7;
        *v = 0;
    }
    return p;
}

void sweep_porous(tallies *ts, soak_rng *r, int n)
{
    for (int i = 0; i < n; ++i) {
        double pb = call_pbad(r);
        int v = 1;
        double m = arg(r, 0.0, SOAK_POROUS_M_MAX, pb, &v), ci = arg(r, 0.0, 1.0, pb, &v), co = arg(r, 0.0, 1.0, pb, &v);
        double x = NAN;
        REC("porous_Gp", v, soak_porous_Gp(m, ci, co, &x), in01(x));
        int vn = 1;
        double sp = arg(r, 0.0, SOAK_POROUS_SP_MAX, pb, &vn), ti = arg(r, 0.0, 0.5 * SOAK_PI, pb, &vn),
               to = arg(r, 0.0, 0.5 * SOAK_PI, pb, &vn);
        x = NAN;
        REC("porous_nb", vn, soak_porous_nb(sp, ti, to, &x), nonneg(x));
        int vap = 1;
        double ka = arg(r, 0.0, 1.0, pb, &vap), nb = arg(r, 0.0, SOAK_POROUS_NB_MAX, pb, &vap);
        x = NAN;
        REC("porous_Ap", vap, soak_porous_Ap(ka, nb, &x), in01(x));
        int vt = 1;
        double t = arg(r, -1.7976931348623157e308, 1.7976931348623157e308, pb, &vt),
               t0 = arg(r, -1.7976931348623157e308, 1.7976931348623157e308, pb, &vt),
               tf = arg(r, 0.0, 1.7976931348623157e308, pb, &vt);
        x = NAN;
        REC("fill_fraction", vt, soak_fill_fraction(t, t0, tf, &x), in01(x));
        int vw = 1;
        double wv = arg(r, 0.0, 1.0, pb, &vw);
        x = NAN;
        REC("wetmap_t0", vw, soak_wetmap_t0(wv, &x), in01(x));

        int vp = 1;
        soak_porous_params p = pick_porous(r, pb, &vp);
        REC("porous_validate", vp, soak_porous_validate(&p), 1);
        int ve = vp, u1, p1, u2, p2;
        double fill = arg(r, 0.0, 1.0, pb, &ve);
        soak_vec3 wi = pick_dir(r, pb, &u1, &p1), wo = pick_dir(r, pb, &u2, &p2);
        ve = ve && u1 && u2;
        soak_porous_coeffs c;
        memset(&c, 0xff, sizeof c);
        REC("porous_coeffs_eval", ve, soak_porous_coeffs_eval(&p, fill, wi, wo, &c),
            in01(c.Gp) && nonneg(c.nb) && in01(c.Ap) && nonneg(c.kd_wet) && nonneg(c.ks_mat) && nonneg(c.ks_water));
        x = NAN;
        REC("porous_eval", ve, soak_porous_eval(&p, fill, wi, wo, &x), nonneg(x));
        x = NAN;
        REC("porous_pdf", ve, soak_porous_pdf(&p, fill, wi, wo, &x), nonneg(x));
        int vs = vp && u1;
        double fs = arg(r, 0.0, 1.0, pb, &vs), ul = arg(r, 0.0, 1.0, pb, &vs), ua = arg(r, 0.0, 1.0, pb, &vs),
               ub = arg(r, 0.0, 1.0, pb, &vs);
        soak_vec3 so = soak_v3(NAN, NAN, NAN);
        double f = NAN, pdf = NAN;
        REC("porous_sample", vs, soak_porous_sample(&p, fs, wi, ul, ua, ub, &so, &f, &pdf),
            unit_out(so) && nonneg(f) && nonneg(pdf));
        if (i % 64 == 0) {
            double alb = NAN, fac = NAN;
            int vf = vp;
            double fa = arg(r, 0.0, 1.0, pb, &vf);
            REC("porous_albedo_factor", vf, soak_porous_albedo_factor(&p, fa, &alb, &fac), in01(alb) && in01(fac));
        }
    }
}

static soak_porous_ggx_params pick_porous_ggx(soak_rng *r, double pb, int *v)
{
    soak_porous_ggx_params q = {arg(r, 0.0, 1.0, pb, v),
                                arg(r, SOAK_GGX_ALPHA_MIN, 1.0, pb, v),
                                uni(r) < 0.2 ? 1.0 : arg(r, 1.0, 3.0, pb, v),
                                arg(r, 0.0, 1.0, pb, v),
                                arg(r, 0.0, SOAK_POROUS_SP_MAX, pb, v),
                                arg(r, SOAK_GGX_ALPHA_MIN, 1.0, pb, v),
                                uni(r) < 0.2 ? 1.0 : arg(r, 1.0, 3.0, pb, v)};
    return q;
}

/* Set-up costs ~30 ms: a few valid ones, many rejected ones (cheap). */
void sweep_porous_ggx(tallies *ts, soak_rng *r, int setups, int evals, long *overflow_ok)
{
    static soak_porous_ggx c; /* large; one at a time */
    int valid_setups = 0;
    for (int s = 0; s < setups; ++s) {
        int v = 1;
        soak_porous_ggx_params q = pick_porous_ggx(r, valid_setups >= 5 ? 1.0 : 0.3, &v);
        REC("porous_ggx_validate", v, soak_porous_ggx_validate(&q), 1);
        if (v && valid_setups >= 5) continue;
        soak_status st = soak_porous_ggx_setup(&q, &c);
        REC("porous_ggx_setup", v, st, 1);
        if (st != SOAK_OK) continue;
        ++valid_setups;
        for (int i = 0; i < evals; ++i) {
            double pb = call_pbad(r);
            int ve = 1, u1, p1, u2, p2;
            double fill = arg(r, 0.0, 1.0, pb, &ve);
            soak_vec3 wi = pick_dir(r, pb, &u1, &p1), wo = pick_dir(r, pb, &u2, &p2);
            double x = NAN;
            int vv = ve && u1 && u2;
            soak_status st = soak_porous_ggx_eval(&c, fill, wi, wo, &x);
            if (vv && st == SOAK_ERR_NUMERIC && wi.z < 1e-300 && wo.z < 1e-300) { /* GGX overflow, soak/ggx.h */
                ++*overflow_ok;
                st = SOAK_ERR_ARG, vv = 0;
            }
            REC("porous_ggx_eval", vv, st, nonneg(x));
            x = NAN;
            REC("porous_ggx_pdf", ve && u1 && u2, soak_porous_ggx_pdf(&c, fill, wi, wo, &x), nonneg(x));
            int vs = ve && u1;
            double ul = arg(r, 0.0, 1.0, pb, &vs), ua = arg(r, 0.0, 1.0, pb, &vs), ub = arg(r, 0.0, 1.0, pb, &vs);
            soak_vec3 so = soak_v3(NAN, NAN, NAN);
            double f = NAN, pdf = NAN;
            st = soak_porous_ggx_sample(&c, fill, wi, ul, ua, ub, &so, &f, &pdf);
            if (vs && st == SOAK_ERR_NUMERIC && fabs(wi.z) <= 1e-300) {
                ++*overflow_ok;
                st = SOAK_ERR_ARG, vs = 0;
            }
            REC("porous_ggx_sample", vs, st, unit_out(so) && nonneg(f) && nonneg(pdf));
            int vc = ve;
            double cs = arg(r, 0.0, 1.0, pb, &vc);
            x = NAN;
            REC("porous_ggx_spec_albedo", vc, soak_porous_ggx_spec_albedo(&c, fill, cs, &x), in01(x));
            if (i % 256 == 0) {
                double alb = NAN, fac = NAN;
                REC("porous_ggx_albedo_factor", ve, soak_porous_ggx_albedo_factor(&c, fill, &alb, &fac),
                    in01(alb) && in01(fac));
            }
        }
    }
}

/* Porous fill darkens: the diffuse coefficient and both darkening factors
 * are non-increasing in the fill fraction ([Hnat06] Eq. 2). */
void monotone_porous(soak_rng *r)
{
    long rises = 0, sets = 0;
    for (int s = 0; s < 60; ++s) {
        int v = 1;
        soak_porous_params p = pick_porous(r, 0.0, &v);
        if (!v) continue;
        ++sets;
        double prev = 2.0;
        for (int k = 0; k <= 10; ++k) {
            double fac = NAN;
            soak_porous_albedo_factor(&p, k / 10.0, NULL, &fac);
            if (!(fac <= prev + 1e-12)) ++rises;
            prev = fac;
        }
    }
    char what[128];
    snprintf(what, sizeof what, "porous darkening factor non-increasing in fill (%ld parameter sets, rises %ld)", sets,
             rises);
    check_true(what, rises == 0 && sets > 20);
}

/* ---- ww.h --------------------------------------------------------------- */

static soak_ww pick_ww(soak_rng *r, double pb, int *v)
{
    soak_ww m;
    m.base = uni(r) < 0.5 ? SOAK_WW_DIELECTRIC : SOAK_WW_CONDUCTOR;
    m.n_water = uni(r) < 0.2 ? 1.0 : arg(r, SOAK_WW_N_WATER_MIN, SOAK_WW_N_WATER_MAX, pb, v);
    m.absorption = arg(r, 0.0, SOAK_WW_ABSORPTION_MAX, pb, v);
    m.thickness = arg(r, 0.0, SOAK_WW_THICKNESS_MAX, pb, v);
    m.alpha = arg(r, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX, pb, v);
    if (m.base == SOAK_WW_DIELECTRIC) {
        m.n_base = arg(r, SOAK_WW_N_DIELECTRIC_MIN, SOAK_WW_N_DIELECTRIC_MAX, pb, v);
        m.kd = arg(r, 0.0, 1.0, pb, v);
        m.k_base = uni(r) < pb ? NAN : 0.0; /* ignored field, but NaN is still rejected */
        if (m.k_base != m.k_base) *v = 0;
    } else {
        m.n_base = arg(r, SOAK_WW_N_CONDUCTOR_MIN, SOAK_WW_N_CONDUCTOR_MAX, pb, v);
        m.k_base = arg(r, 0.0, SOAK_WW_K_MAX, pb, v);
        m.kd = uni(r) < pb ? INFINITY : 0.5;
        if (!fin(m.kd)) *v = 0;
    }
    if (uni(r) < pb * 0.2) {
        m.base = (soak_ww_base)3;
        *v = 0;
    }
    return m;
}

void sweep_ww(tallies *ts, soak_rng *r, int n, long *overflow_ok)
{
    for (int i = 0; i < n; ++i) {
        double pb = call_pbad(r);
        int v = 1;
        soak_ww m = pick_ww(r, pb, &v);
        REC("ww_validate", v, soak_ww_validate(&m), 1);
        int u1, p1, u2, p2;
        soak_vec3 wi = pick_dir(r, pb, &u1, &p1), wo = pick_dir(r, pb, &u2, &p2);
        int grazing = p1 && p2 && wi.z < 1e-300 && wo.z < 1e-300;
        double x = NAN;
        int ve = v && p1 && p2;
        soak_status st = soak_ww_eval(&m, wi, wo, &x);
        if (ve && st == SOAK_ERR_NUMERIC && grazing) { /* the GGX base's documented overflow */
            ++*overflow_ok;
            st = SOAK_ERR_ARG, ve = 0;
        }
        REC("ww_eval", ve, st, nonneg(x));
        x = NAN;
        ve = v && p1 && p2;
        st = soak_ww_base_eval(&m, wi, wo, &x);
        if (ve && st == SOAK_ERR_NUMERIC && grazing) {
            ++*overflow_ok;
            st = SOAK_ERR_ARG, ve = 0;
        }
        REC("ww_base_eval", ve, st, nonneg(x));
        int vc = v;
        double c = arg(r, 0.0, 1.0, pb, &vc);
        x = NAN;
        REC("ww_specular", vc, soak_ww_specular(&m, c, &x), in01(x));
        int vs = v && p2;
        double ua = arg(r, 0.0, 1.0, pb, &vs), ub = arg(r, 0.0, 1.0, pb, &vs), uc = arg(r, 0.0, 1.0, pb, &vs);
        soak_vec3 so = soak_v3(NAN, NAN, NAN);
        double w = NAN, pdf = NAN;
        int delta = -1;
        st = soak_ww_sample(&m, wo, ua, ub, uc, &so, &w, &pdf, &delta);
        if (vs && st == SOAK_ERR_NUMERIC && wo.z < 1e-300) {
            ++*overflow_ok;
            st = SOAK_ERR_ARG, vs = 0;
        }
        REC("ww_sample", vs, st, unit_out(so) && nonneg(w) && nonneg(pdf) && (delta == 0 || delta == 1));

        int vf = 1;
        double n2 = arg(r, SOAK_ETA_MIN, SOAK_ETA_MAX, pb, &vf), n3 = arg(r, SOAK_ETA_MIN, SOAK_ETA_MAX, pb, &vf);
        x = NAN;
        REC("triace_fbottom_dielectric", vf, soak_triace_fbottom_dielectric(n2, n3, &x), in01(x));
        double k3 = arg(r, 0.0, SOAK_ETA_MAX, pb, &vf);
        x = NAN;
        REC("triace_fbottom_conductor", vf, soak_triace_fbottom_conductor(n2, n3, k3, &x), in01(x));
        int va = 1;
        double ap = arg(r, 0.0, 1e9, pb, &va);
        double cl = uni(r) < pb ? pick_invalid(r, 0.0, 1.0) : nextafter(pick_valid(r, 0.0, 1.0), 2.0);
        double cv = uni(r) < pb ? pick_invalid(r, 0.0, 1.0) : nextafter(pick_valid(r, 0.0, 1.0), 2.0);
        if (cl > 1.0) cl = 1.0;
        if (cv > 1.0) cv = 1.0;
        va = va && cl > 0.0 && cl <= 1.0 && cv > 0.0 && cv <= 1.0; /* (0, 1] */
        x = NAN;
        REC("triace_absorption_linear", va, soak_triace_absorption_linear(ap, cl, cv, &x), in01(x));
        int ui, pi, un, pn;
        soak_vec3 inc = pick_dir(r, pb, &ui, &pi), nrm = pick_dir(r, pb, &un, &pn);
        soak_vec3 t = soak_v3(NAN, NAN, NAN);
        int vr = ui && un && soak_v3_dot(inc, nrm) <= 1e-6;
        st = soak_refract_1_33(inc, nrm, &t);
        if (ui && un && fabs(soak_v3_dot(inc, nrm)) <= 2e-5) vr = st == SOAK_OK; /* the tolerance band */
        REC("refract_1_33", vr, st, fin(t.x) && fin(t.y) && fin(t.z) && soak_v3_dot(t, nrm) <= 1e-9);

        if (i % 4 == 0) {
            soak_ww_triace fast;
            int vt = v && m.n_water >= SOAK_WW_TRIACE_N_MIN && m.n_water <= SOAK_WW_TRIACE_N_MAX &&
                     m.absorption * m.thickness <= 1e9;
            st = soak_ww_triace_setup(&m, &fast);
            REC("ww_triace_setup", vt, st, 1);
            if (st == SOAK_OK)
                for (int k = 0; k < 4; ++k) {
                    soak_vec3 a = pick_dir(r, pb, &u1, &p1), b = pick_dir(r, pb, &u2, &p2);
                    x = NAN;
                    REC("ww_eval_triace", p1 && p2, soak_ww_eval_triace(&fast, a, b, &x), nonneg(x));
                }
        }
    }
}

static soak_model_params pick_model_params(soak_rng *r, double pb, int *v)
{
    soak_model_params p;
    soak_model_params_default(&p);
    /* each field gets an adversarial value inside or outside its widest
     * meaningful range, or stays at its default */
    double *f[] = {&p.albedo,    &p.ior,      &p.k,  &p.roughness, &p.n_film, &p.absorption,
                   &p.thickness, &p.porosity, &p.sp, &p.fill,      &p.ks,     &p.ks_water};
    for (size_t i = 0; i < sizeof f / sizeof f[0]; ++i) {
        double u = uni(r);
        if (u < pb) {
            *f[i] = pick_invalid(r, 0.0, 1.0);
        } else if (u < 0.6) {
            static const double lo[] = {0, 1, 0, 1e-4, 1, 0, 0, 0, 0, 0, 0, 0};
            static const double hi[] = {1, 3, 5, 1, 3, 1e3, 1, 1, 20, 1, 1, 1};
            *f[i] = pick_valid(r, lo[i], hi[i]);
        }
    }
    if (uni(r) < 0.3) p.k = 0.0;
    if (uni(r) < 0.3) p.ks = 0.0;
    for (size_t i = 0; i < sizeof f / sizeof f[0]; ++i)
        if (!fin(*f[i])) *v = 0;
    return p;
}

void sweep_models(tallies *ts, soak_rng *r, int evals_per_model, long *overflow_ok)
{
    size_t n;
    const soak_model *models = soak_models(&n);
    static soak_model_ctx ctx;
    for (size_t i = 0; i < n; ++i) {
        const soak_model *m = &models[i];
        int expensive = !strcmp(m->name, "porous-ggx");
        int setups = expensive ? 40 : 400, good = 0, budget = evals_per_model;
        for (int s = 0; s < setups; ++s) {
            int v = 1;
            double pb = expensive && good >= 3 ? 1.0 : 0.3;
            soak_model_params p = pick_model_params(r, pb, &v);
            if (expensive && good >= 3 && v) continue;
            soak_status st = m->setup(&p, &ctx);
            /* a NaN/Inf anywhere must be rejected; finite values may still be
             * outside the model's own range (rejected or not) */
            REC("models_setup (NaN/Inf rejected)", v, v ? SOAK_OK : st, 1);
            if (st != SOAK_OK) continue;
            ++good;
            int per = budget < 1000 ? budget : 1000;
            if (expensive) per = budget < evals_per_model / 3 ? budget : evals_per_model / 3;
            budget -= per;
            for (int k = 0; k < per; ++k) {
                double pbd = call_pbad(r);
                int u1, p1, u2, p2;
                soak_vec3 wi = pick_dir(r, pbd, &u1, &p1), wo = pick_dir(r, pbd, &u2, &p2);
                double x = NAN;
                st = soak_model_eval(m, &ctx, wi, wo, &x);
                int ve = u1 && u2;
                if (ve && st == SOAK_ERR_NUMERIC && p1 && p2 && wi.z < 1e-300 && wo.z < 1e-300) {
                    ++*overflow_ok;
                    st = SOAK_ERR_ARG, ve = 0;
                }
                REC(m->name, ve, st, nonneg(x) && x <= 1e300);
            }
        }
        char what[128];
        snprintf(what, sizeof what, "%s: some adversarial set-ups succeed (%d)", m->name, good);
        check_true(what, good > 0);
    }
}
