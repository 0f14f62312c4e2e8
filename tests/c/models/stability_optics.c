/* Stability sweeps of the optics headers: Fresnel, GGX, phase functions,
 * the film (issue 20; driver: test_stability.c). */
#include "stability_args.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "soak/film.h"
#include "soak/fresnel.h"
#include "soak/ggx.h"
#include "soak/hg.h"
#include "soak/jensen.h"
#include "soak/vdhulst.h"
#include "check.h"

/* ---- fresnel.h ---------------------------------------------------------- */

void sweep_fresnel(tallies *ts, soak_rng *r, int n)
{
    for (int i = 0; i < n; ++i) {
        double pb = call_pbad(r);
        int v = 1;
        double c = arg(r, 0.0, 1.0, pb, &v);
        /* equal indices and indices either side of 1 (TIR) are frequent */
        double eta = uni(r) < 0.2 ? 1.0 : arg(r, SOAK_ETA_MIN, SOAK_ETA_MAX, pb, &v);
        double R = NAN, ct = NAN;
        soak_status st = soak_fresnel_dielectric(c, eta, &R, &ct);
        REC("fresnel_dielectric", v, st, in01(R) && in01(ct));

        int vk = v;
        double k = uni(r) < 0.3 ? pick_valid(r, 0.0, 1e-150) : arg(r, 0.0, SOAK_ETA_MAX, pb, &vk);
        R = NAN;
        st = soak_fresnel_conductor(c, eta, k, &R);
        REC("fresnel_conductor", vk, st, in01(R));

        int vs = 1;
        double cs = arg(r, 0.0, 1.0, pb, &vs), r0 = arg(r, 0.0, 1.0, pb, &vs);
        R = NAN;
        REC("fresnel_schlick", vs, soak_fresnel_schlick(cs, r0, &R), in01(R));

        int v0 = 1;
        double e0 = arg(r, SOAK_ETA_MIN, SOAK_ETA_MAX, pb, &v0), k0 = arg(r, 0.0, SOAK_ETA_MAX, pb, &v0);
        R = NAN;
        REC("fresnel_r0", v0, soak_fresnel_r0(e0, k0, &R), in01(R));
        if (i % 16 == 0) {
            int va = 1;
            double ea = uni(r) < 0.2 ? 1.0 : arg(r, SOAK_ETA_MIN, SOAK_ETA_MAX, pb, &va);
            R = NAN;
            REC("fresnel_dielectric_avg", va, soak_fresnel_dielectric_avg(ea, &R), in01(R));
        }
    }
}

/* Unpolarised dielectric reflectance is non-decreasing in the angle of
 * incidence (both directions, through the critical angle) for the indices
 * of materials and liquids, 1/3..3. (Not beyond: for eta ~ 1e3 the p-wave's
 * Brewster dip makes the average fall just before grazing.) */
void monotone_fresnel(void)
{
    const double etas[] = {1.0 / 3.0, 0.5, 1.0 / 1.333, 0.999999, 1.0, 1.000001, 1.333, 1.5, 2.0, 3.0};
    long drops = 0;
    double worst = 0.0;
    for (size_t e = 0; e < sizeof etas / sizeof etas[0]; ++e) {
        double prev = -1.0;
        for (int k = 20000; k >= 0; --k) {
            double R;
            soak_fresnel_dielectric(k / 20000.0, etas[e], &R, NULL);
            if (R < prev - 1e-15) {
                ++drops;
                worst = fmax(worst, prev - R);
            }
            prev = R;
        }
    }
    char what[128];
    snprintf(what, sizeof what, "dielectric Fresnel non-decreasing with angle, 10 indices x 20001 angles (drops %ld)",
             drops);
    check_true(what, drops == 0);
}

/* ---- ggx.h -------------------------------------------------------------- */

void sweep_ggx(tallies *ts, soak_rng *r, int n, long *overflow_ok)
{
    for (int i = 0; i < n; ++i) {
        double pb = call_pbad(r);
        int va = 1, ui, pi, uo, po;
        double a = arg(r, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX, pb, &va);
        soak_vec3 wi = pick_dir(r, pb, &ui, &pi), wo = pick_dir(r, pb, &uo, &po);
        double x = NAN;
        REC("ggx_D", va && ui, soak_ggx_D(a, wi, &x), nonneg(x));
        x = NAN;
        REC("ggx_G1", va && pi, soak_ggx_G1(a, wi, &x), in01(x));
        x = NAN;
        REC("ggx_G2", va && pi && po, soak_ggx_G2(a, wi, wo, &x), in01(x));

        int ve = va && pi && po;
        double eta = uni(r) < 0.2 ? 1.0 : arg(r, SOAK_ETA_MIN, SOAK_ETA_MAX, pb, &ve);
        /* documented overflow: both cosines below 1e-300 */
        int grazing = pi && po && wi.z < 1e-300 && wo.z < 1e-300;
        x = NAN;
        soak_status st = soak_ggx_brdf_dielectric(a, eta, wi, wo, &x);
        if (ve && st == SOAK_ERR_NUMERIC && grazing) {
            ++*overflow_ok;
            st = SOAK_ERR_ARG, ve = 0; /* counted apart, not as a rejection of valid input */
        }
        REC("ggx_brdf_dielectric", ve, st, nonneg(x));
        int vk = va && pi && po;
        double ek = arg(r, SOAK_ETA_MIN, SOAK_ETA_MAX, pb, &vk), k = arg(r, 0.0, SOAK_GGX_K_MAX, pb, &vk);
        x = NAN;
        st = soak_ggx_brdf_conductor(a, ek, k, wi, wo, &x);
        if (vk && st == SOAK_ERR_NUMERIC && grazing) {
            ++*overflow_ok;
            st = SOAK_ERR_ARG, vk = 0;
        }
        REC("ggx_brdf_conductor", vk, st, nonneg(x));

        int vu = va && pi;
        double u1 = arg(r, 0.0, 1.0, pb, &vu), u2 = arg(r, 0.0, 1.0, pb, &vu);
        soak_vec3 h = soak_v3(NAN, NAN, NAN);
        double pdf = NAN;
        st = soak_ggx_sample_vndf(a, wi, u1, u2, &h, &pdf);
        REC("ggx_sample_vndf", vu, st, unit_out(h) && h.z > 0.0 && nonneg(pdf));
        pdf = NAN;
        REC("ggx_pdf_vndf", va && pi && uo, soak_ggx_pdf_vndf(a, wi, wo, &pdf), nonneg(pdf));
    }
}

/* ---- hg.h, vdhulst.h, jensen.h ----------------------------------------- */

void sweep_phase(tallies *ts, soak_rng *r, int n)
{
    for (int i = 0; i < n; ++i) {
        double pb = call_pbad(r);
        int vg = 1;
        double g = arg(r, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, pb, &vg);
        int vc = vg;
        double c = arg(r, -1.0, 1.0, pb, &vc);
        double x = NAN;
        REC("hg_eval", vc, soak_hg_eval(g, c, &x), nonneg(x));
        int vu = vg;
        double u = arg(r, 0.0, 1.0, pb, &vu);
        x = NAN;
        REC("hg_sample_cos", vu, soak_hg_sample_cos(g, u, &x), rng_ok(x, -1.0, 1.0));

        int vp = 1;
        soak_hg2 p = {arg(r, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, pb, &vp), arg(r, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, pb, &vp),
                      arg(r, 0.0, 1.0, pb, &vp)};
        REC("hg2_validate", vp, soak_hg2_validate(&p), 1);
        int v2 = vp;
        double c2 = arg(r, -1.0, 1.0, pb, &v2);
        x = NAN;
        REC("hg2_eval", v2, soak_hg2_eval(&p, c2, &x), nonneg(x));
        if (vp) {
            double mc = soak_hg2_mean_cosine(&p);
            REC("hg2_mean_cosine", 1, SOAK_OK, rng_ok(mc, -1.0, 1.0));
        }
        int vs = vp, un, upn;
        soak_vec3 d = pick_dir(r, pb, &un, &upn);
        /* hg2_sample accepts |dir_in| within 1e-3 of 1 (its own tolerance) */
        double len = sqrt(soak_v3_dot(d, d));
        vs = vs && len >= 0.999 && len <= 1.001;
        double ul = arg(r, 0.0, 1.0, pb, &vs), uc = arg(r, 0.0, 1.0, pb, &vs), up = arg(r, 0.0, 1.0, pb, &vs);
        soak_vec3 out = soak_v3(NAN, NAN, NAN);
        x = NAN;
        soak_status st = soak_hg2_sample(&p, d, ul, uc, up, &out, &x);
        REC("hg2_sample", vs, st, unit_out(out) && nonneg(x));

        int vo = 1;
        double om = arg(r, 0.0, 1.0, pb, &vo), gg = arg(r, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, pb, &vo);
        x = NAN;
        REC("vdhulst_albedo", vo, soak_vdhulst_albedo(om, gg, &x), in01(x));
        x = NAN;
        REC("vdhulst_invert", vo, soak_vdhulst_invert(om, gg, &x), in01(x));

        int vj = 1;
        soak_jensen_layer l = {arg(r, 1.0, 3.0, pb, &vj), uni(r) < 0.3 ? 1.0 : arg(r, 1.0, 3.0, pb, &vj),
                               arg(r, 1.0, 3.0, pb, &vj), arg(r, 0.01, 100.0, pb, &vj)};
        REC("jensen_validate", vj, soak_jensen_validate(&l), 1);
        int vjc = vj;
        double cj = arg(r, 0.0, 1.0, pb, &vjc);
        double T = NAN, co = NAN;
        int tir = -1;
        REC("jensen_transmit_down", vjc, soak_jensen_transmit_down(&l, cj, &T, &co), in01(T) && in01(co));
        T = co = NAN;
        REC("jensen_transmit_up", vjc, soak_jensen_transmit_up(&l, cj, &T, &co, &tir),
            in01(T) && in01(co) && (tir == 0 || tir == 1));
        T = NAN;
        /* (n1/n3)^2 T_up <= 1 for n3 >= n1 ... and <= 9 for indices in [1, 3] */
        REC("jensen_radiance_out", vjc, soak_jensen_radiance_out(&l, cj, &T), rng_ok(T, 0.0, 9.0));
        T = NAN;
        REC("jensen_reflect_top", vjc, soak_jensen_reflect_top(&l, cj, &T), in01(T));
        T = NAN;
        REC("jensen_shadow", vjc, soak_jensen_shadow(&l, cj, &T), in01(T));
    }
}

/* ---- film.h ------------------------------------------------------------- */

static soak_film pick_film(soak_rng *r, double pb, int *v)
{
    soak_film f = {uni(r) < 0.2 ? 1.0 : arg(r, 1.0, 3.0, pb, v), arg(r, 0.0, 1e6, pb, v), arg(r, 0.0, 1e3, pb, v)};
    return f;
}

void sweep_film(tallies *ts, soak_rng *r, int n)
{
    for (int i = 0; i < n; ++i) {
        double pb = call_pbad(r);
        int vf = 1;
        soak_film f = pick_film(r, pb, &vf);
        REC("film_validate", vf, soak_film_validate(&f), 1);
        soak_film_ctx ctx;
        memset(&ctx, 0, sizeof ctx);
        soak_status sc = soak_film_setup(&f, &ctx);
        REC("film_setup", vf, sc, in01(ctx.spec_avg) && in01(ctx.escape) && in01(ctx.ret));
        if (sc != SOAK_OK) soak_film_setup(&(soak_film){1.333, 0.0, 0.0}, &ctx);
        for (int k = 0; k < 8; ++k) {
            int va = 1, u1, p1, u2, p2;
            double alb = arg(r, 0.0, 1.0, pb, &va), c = arg(r, 0.0, 1.0, pb, &va);
            soak_vec3 wi = pick_dir(r, pb, &u1, &p1), wo = pick_dir(r, pb, &u2, &p2);
            double x = NAN;
            REC("film_ctx_albedo_dir", va, soak_film_ctx_albedo_dir(&ctx, alb, c, &x), in01(x));
            int vd = 1;
            double alb2 = arg(r, 0.0, 1.0, pb, &vd);
            x = NAN;
            REC("film_ctx_albedo_diffuse", vd, soak_film_ctx_albedo_diffuse(&ctx, alb2, &x), in01(x));
            x = NAN;
            REC("film_ctx_brdf", vd && u1 && u2, soak_film_ctx_brdf(&ctx, alb2, wi, wo, &x), nonneg(x));
            if (k == 0) {
                x = NAN;
                REC("film_albedo_dir", va && vf, soak_film_albedo_dir(&f, alb, c, &x), in01(x));
                x = NAN;
                REC("film_albedo_diffuse", vd && vf, soak_film_albedo_diffuse(&f, alb2, &x), in01(x));
                x = NAN;
                REC("film_brdf", vd && vf && u1 && u2, soak_film_brdf(&f, alb2, wi, wo, &x), nonneg(x));
                int vc = vf;
                double cs = arg(r, 0.0, 1.0, pb, &vc);
                x = NAN;
                REC("film_specular", vc, soak_film_specular(&f, cs, &x), in01(x));
            }
        }
    }
}

/* The film's mirror reflectance rises with the angle of incidence; so does
 * its total reflectance when nothing absorbs (F + (1 - F) * constant). */
void monotone_film(void)
{
    const double ns[] = {1.0, 1.0001, 1.333, 1.5, 3.0};
    const double albs[] = {0.0, 0.3, 1.0};
    long drops = 0;
    for (size_t a = 0; a < sizeof ns / sizeof ns[0]; ++a) {
        soak_film f = {ns[a], 0.0, 1e-3};
        soak_film_ctx ctx;
        soak_film_setup(&f, &ctx);
        double prev_s = -1.0, prev_t[3] = {-1.0, -1.0, -1.0};
        for (int k = 2000; k >= 0; --k) {
            double c = k / 2000.0, s;
            soak_film_specular(&f, c, &s);
            if (s < prev_s - 1e-14) ++drops;
            prev_s = s;
            for (int b = 0; b < 3; ++b) {
                double t;
                soak_film_ctx_albedo_dir(&ctx, albs[b], c, &t);
                if (t < prev_t[b] - 1e-12) ++drops;
                prev_t[b] = t;
            }
        }
    }
    char what[128];
    snprintf(what, sizeof what,
             "film reflectance (mirror; total without absorption) non-decreasing with angle (drops %ld)", drops);
    check_true(what, drops == 0);
}
