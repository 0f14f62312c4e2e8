/* Porous surfaces, dry and wet.
 *
 * 1. Merillou, Dischler, Ghazanfarpour, "A BRDF postprocess to integrate
 *    porosity on rendered surfaces", IEEE TVCG 6(4), 2000, as summarised in
 *    [Hnat06] sec. 3.1 and [Lag13] "Real time porous material": a separable
 *    BRDF k_s F_s + k_d F_d gets new coefficients k_s-poro, k_d-poro built from
 *    the pore shadowing/masking G_p, the pore light loss A_p and the mean
 *    number of bounces n_b inside a pore.
 * 2. Hnat, Porquet, Merillou, Ghazanfarpour, "Real-time wetting of porous
 *    media" ([Hnat06] sec. 3.2-3.3, Eq. 2-3): pores fill with water over a
 *    time t_fill; the porous diffuse part fades out and a water specular lobe
 *    fades in with the fill fraction dt/t_fill.
 * 3. soak_porous_ggx_*: our energy-conserving variant on a GGX base (see the
 *    comment above soak_porous_ggx_params).
 *
 * Corrections to the sources (each is tested in tests/c/models/test_porous.c):
 *  - G_p: [Hnat06] Eq. 1 prints Schlick's constant as k = 2 m^2 / pi; [Lag13]
 *    gives k = sqrt(2 m^2 / pi), Schlick's (1994) form for RMS slope m. We use
 *    the square root: Smith masking depends on the slope only through
 *    cos / (m sin), so the knee of the Schlick rational must scale linearly
 *    with m; k = 2 m^2 / pi scales with m^2, which is dimensionally wrong.
 *    (Schlick's rational is only a rough fit of Smith-Beckmann: the shapes
 *    differ by up to ~0.4 near grazing whatever k; we keep the published
 *    model.)
 *  - n_b: [Hnat06] drops the square of the bracket; [Lag13]'s shader code
 *    multiplies acos(N.V) * acos(N.L) where its own formula (and [Hnat06])
 *    averages the two angles (a typo: sum, not product).
 *  - n_b is clamped to >= 0 (not >= 1): the fit is proportional to s_p, so a
 *    pore of zero depth (s_p -> 0) must give no extra loss (A_p -> 0); the
 *    first bounce is already carried by the factor (k_s + k_d) of the porous
 *    term. The fit turns negative for s_p >~ 23.8 near grazing, where it would
 *    make A_p < 0 (a pore brighter than the flat surface): that is what the
 *    clamp removes.
 *  - A_p = k_a (1 - (1-k_a)^n_b) / (1 - (1-k_a)) is a geometric sum equal to
 *    1 - (1-k_a)^n_b; [Lag13] says the published [Hnat06] misses the power
 *    n_b (our extraction of [Hnat06] has it). Evaluated as
 *    -expm1(n_b log1p(-k_a)):
 *    no 0/0 at k_a = 0 and full relative precision for tiny k_a.
 *  - Eq. 3 of [Hnat06] adds k_s-water to the coefficient of the material's
 *    own specular lobe, although the text calls the water "almost mirror-like";
 *    [Lag13] gives the water its own Blinn-Phong lobe (power 200). We follow
 *    [Lag13]: the water term has its own exponent (water_power).
 *  - [Lag13]'s "simplified" form (1 - a G_p) f_r + a G_p (k_s+k_d)^(n_b+1) F_d
 *    is algebraically IDENTICAL to the k_s-poro/k_d-poro form of [Hnat06] when
 *    k_a = 1 - k_s - k_d (expand: k_d (1 - aG_p) + aG_p (1-A_p)(k_s+k_d)
 *    = k_d (1 - aG_p A_p) + k_s aG_p (1-A_p), and 1 - A_p = (k_s+k_d)^n_b).
 *    It differs only if k_a is taken independently of k_s + k_d. Tested.
 *
 * Directions: unit vectors in the local frame (normal +z), within 1e-6 of
 * unit length. A pair with wi.z <= 0 or wo.z <= 0 gives f = 0 (SOAK_OK).
 * Values are per colour channel: call once per channel for RGB. */
#ifndef SOAK_POROUS_H
#define SOAK_POROUS_H

#include "soak/status.h"
#include "soak/vec.h"

#define SOAK_POROUS_M_MAX 1.0      /* RMS slope range [0, 1] ([Hnat06] Tab. 1) */
#define SOAK_POROUS_SP_MAX 50.0    /* pore depth / diameter */
#define SOAK_POROUS_POWER_MAX 1e4  /* Blinn-Phong exponents */
#define SOAK_POROUS_NB_MAX 1e4     /* accepted by soak_porous_Ap */
/* Upper bound of ks_water, the reflectance of the water surface in a
 * filled pore (a liquid's F0 is <= 0.25 for indices <= 3). Why a bound:
 * Merillou's weights (1 - a G_p) and a G_p use G_p = G1(wi) G1(wo), so the
 * directional albedo is E_mat(wi) + a G1(wi) int G1(wo) (f_pore - f_mat)
 * cos_o dwo. The pores' diffuse term never exceeds the material lobes it
 * displaces, but a mirror-like water lobe sits where G1(wo) is largest
 * while a diffuse material lobe is partly masked: for k_d = 1 at normal
 * incidence the albedo is 1 + a (ks_water - M), M = 2 int_0^1 G1(mu) mu dmu
 * >= 0.703 (its value at m = 1). ks_water <= 0.5 < 0.703 keeps the albedo
 * <= 1 (white furnace over k_d, k_s, m, porosity, s_p, fill, ks_water in
 * tests/c/models/test_stability.c); ks_water = 1 reflected up to 1.29. */
#define SOAK_POROUS_KS_WATER_MAX 0.5

/* ---- building blocks ---- */

/* Schlick-Smith pore shadowing/masking ([Hnat06] Eq. 1, corrected k):
 * G_p = G1(cos_i) G1(cos_o), G1(c) = c / (c (1 - k) + k), k = m sqrt(2/pi).
 * cos in [0,1]; G1(0) = 0 for every m (also m = 0, the limit from c > 0 being
 * 1 there is a discontinuity we resolve towards the grazing value). */
soak_status soak_porous_Gp(double m, double cos_i, double cos_o, double *Gp);

/* Mean number of bounces in a pore ([Hnat06] sec. 3.1, square restored):
 * n_b = s_p [3.7 - 2 ((theta_i + theta_o)/2 - 2 pi / (s_p + 6))^2], clamped
 * to >= 0. Angles in [0, pi/2] (radians), s_p in [0, SOAK_POROUS_SP_MAX]. */
soak_status soak_porous_nb(double sp, double theta_i, double theta_o, double *nb);

/* Light loss in a pore after n_b bounces of absorption k_a each:
 * A_p = 1 - (1 - k_a)^n_b. k_a in [0,1], n_b in [0, SOAK_POROUS_NB_MAX]. */
soak_status soak_porous_Ap(double ka, double nb, double *Ap);

/* Fill fraction dt / t_fill of [Hnat06] sec. 3.3.2:
 *   dt = 0 for t < t0, t - t0 for t0 <= t < t0 + t_fill, t_fill afterwards.
 * t_fill = 0 is instantaneous filling: a step, 0 for t < t0 and 1 for
 * t >= t0. Right-continuous in t for every t_fill (0 before t0, complete
 * at t0 + t_fill), so t_fill = 0 is the ramp's limit at every t except the
 * single instant t0, where it takes the ramp's end value. The ONE schedule:
 * soak_wetness_eval (step 1), the bakes and the OSL math follow it.
 * t, t0 finite, t_fill in [0, +finite]. Result in [0,1], non-decreasing. */
soak_status soak_fill_fraction(double t, double t0, double t_fill, double *frac);

/* Wet-map value to wetting start time. [Hnat06] sec. 3.3.1 stores 1 for
 * "first wet" and 0 for "never wet during the simulation" (t in [0,1]); we
 * map t0 = 1 - value, so value 1 starts filling at t = 0 and value 0 at
 * t = 1, i.e. never within the run (the fill is 0 at t = t0). value in [0,1]. */
soak_status soak_wetmap_t0(double value, double *t0);

/* ---- Merillou + Hnat on Blinn-Phong ([Lag13] code, [Hnat06] Eq. 2-3) ---- */

typedef enum soak_blinn_norm {
    /* cos^n(theta_h) / A(n), A(n) = 8 pi (n + 2^(-n/2)) / ((n+2)(n+4)), the
     * lobe's exact directional albedo at normal incidence: with wo the
     * mirror of wi = +z about h, cos_o = 2 cos_h^2 - 1 and dw_o = 4 cos_h
     * dw_h, so A(n) = 8 pi int_{1/sqrt2}^1 c^(n+1) (2c^2 - 1) dc. The
     * albedo is then exactly 1 at normal incidence and falls towards
     * grazing (measured for n in [0, 1e4], tests/c/models/test_stability.c), so
     * k_s is the fraction of light reflected specularly, as Merillou's
     * k_a = 1 - k_s - k_d requires. Default. (Was Hoffman's (n+8)/(8 pi),
     * SIGGRAPH 2010 course: an approximation of 1/A(n) whose albedo at
     * normal incidence reaches 1.077 near n = 8 -- with k_s = 1 the porous
     * model reflected up to 1.07 of the light.) */
    SOAK_BLINN_NORM_ENERGY = 0,
    /* (n + 2) / (2 pi) cos^n(theta_h), [Lag13]'s shader. This normalises the
     * distribution of half vectors (integral of D cos(theta_h) = 1), not the
     * BRDF lobe: used directly as a BRDF its albedo at normal incidence tends
     * to 4 for large n. Kept to reproduce [Lag13]'s pictures. */
    SOAK_BLINN_NORM_SEED001 = 1
} soak_blinn_norm;

typedef struct soak_porous_params {
    double kd;          /* diffuse coefficient, [0,1] */
    double ks;          /* specular coefficient, [0,1], ks + kd <= 1 */
    double m;           /* RMS slope for G_p, [0, SOAK_POROUS_M_MAX] */
    double spec_power;  /* Blinn-Phong exponent n, [0, SOAK_POROUS_POWER_MAX];
                           [Lag13] links it to m by n = 2/m^2 - 2 */
    double porosity;    /* alpha_poro, fraction of surface in open pores, [0,1] */
    double sp;          /* pore depth / diameter, [0, SOAK_POROUS_SP_MAX] */
    double ks_water;    /* water specular coefficient, [0, SOAK_POROUS_KS_WATER_MAX]
                           ([Lag13]: 0.02, water's F0) */
    double water_power; /* exponent of the water lobe ([Lag13]: 200) */
    soak_blinn_norm norm;
} soak_porous_params;

soak_status soak_porous_validate(const soak_porous_params *p);

/* The coefficients of one direction pair (all dimensionless). */
typedef struct soak_porous_coeffs {
    double Gp, nb, Ap;
    double kd_wet;   /* k_d-poro-wet, [Hnat06] Eq. 2 (k_d-poro at fill 0) */
    double ks_mat;   /* k_s (1 - alpha G_p): material specular, Eq. 3 first term */
    double ks_water; /* k_s-water alpha G_p fill: water specular, Eq. 3 second term */
} soak_porous_coeffs;

/* fill in [0,1] (soak_fill_fraction). Below-horizon pairs give all zeros. */
soak_status soak_porous_coeffs_eval(const soak_porous_params *p, double fill, soak_vec3 wi, soak_vec3 wo,
                                    soak_porous_coeffs *c);

/* f = kd_wet / pi + ks_mat B(spec_power) + ks_water B(water_power), where B is
 * the normalised Blinn-Phong lobe selected by p->norm. Reciprocal. With
 * SOAK_BLINN_NORM_ENERGY the directional albedo is <= 1 for every valid
 * parameter set (see SOAK_BLINN_NORM_ENERGY and SOAK_POROUS_KS_WATER_MAX);
 * SOAK_BLINN_NORM_SEED001 reproduces [Lag13] and is not conserving. */
soak_status soak_porous_eval(const soak_porous_params *p, double fill, soak_vec3 wi, soak_vec3 wo, double *f);

/* Importance sampling: a one-sample mixture of a cosine lobe and the two
 * Blinn-Phong lobes sampled by half vector (pdf_h = (n+1)/(2 pi) cos^n),
 * picked by u_lobe in proportion to bounds of their coefficients. Writes wo,
 * f = eval(wi, wo) and the mixture density pdf (= soak_porous_pdf). A sample
 * below the horizon, or one whose density overflows (a grazing wi reflected
 * straight back, wi.h ~ 1e-310), has f = pdf = 0 ("no sample"). u_lobe, u1,
 * u2 in [0,1]. */
soak_status soak_porous_sample(const soak_porous_params *p, double fill, soak_vec3 wi, double u_lobe, double u1,
                               double u2, soak_vec3 *wo, double *f, double *pdf);
soak_status soak_porous_pdf(const soak_porous_params *p, double fill, soak_vec3 wi, soak_vec3 wo, double *pdf);

/* White-sky (bi-hemispherical) albedo of the diffuse term kd_wet / pi at this
 * fill, (1/pi) int int (kd_wet/pi) cos_i cos_o, and the darkening factor
 * albedo(fill) / albedo(0) (1 when albedo(0) == 0). The albedo is linear in
 * fill. Either output may be NULL. */
soak_status soak_porous_albedo_factor(const soak_porous_params *p, double fill, double *diffuse_albedo,
                                      double *factor);

/* ---- Energy-conserving variant on GGX (porous_ggx.c) ----
 *
 * f = (1 - a G_p) f_mat + a G_p fill f_water + D,  a = porosity,
 *   f_mat   GGX dielectric (roughness, eta): the non-porous surface;
 *   f_water GGX dielectric (water_roughness, eta_water): the water surface in
 *           the filled pores (replaces Eq. 3's k_s-water: F0(1.33) = 0.020,
 *           [Lag13]'s Kwater);
 *   G_p     GGX height-correlated Smith G2 of the material roughness ([Lag13]
 *           suggests G_p = the base BRDF's G);
 *   D = rho_eff (1 - E_s(mu_i)) (1 - E_s(mu_o)) / (pi (1 - E_s_avg)),
 *   rho_eff = albedo (1 - a G_p) + a G_p r (1 - A_p(n_b, k_a = 1 - r)) (1 - fill),
 *   r = the non-porous surface's white-sky albedo E_mat_avg + albedo (1 - E_mat_avg)
 *       (the k_s + k_d of a pore wall),
 *   E_s(mu) = directional albedo of the specular terms, tabulated at setup.
 * The diffuse takes what the specular leaves, Kelemen & Szirmay-Kalos 2001
 * style: the directional albedo is E_s(mu_i) + (1 - E_s(mu_i)) * (a cosine
 * average of rho_eff) <= 1 for every direction, fill and porosity, because
 * rho_eff <= 1 and the normaliser 1 - E_s_avg is computed exactly for the
 * interpolated table. What remains is the table's own error, measured
 * against an independent quadrature at ~1e-6 (tests/c/models/test_porous.c).
 * Reciprocal: every term is symmetric in (wi, wo). Porosity 0 makes fill
 * irrelevant. Light entering filled pores through the water surface is
 * taken as absorbed (the darkening of [Hnat06]).
 * The simpler weight (1 - F(mu_i))(1 - F(mu_o)) bounds the albedo only where
 * the specular albedo E(mu) <= F(mu), which nothing guarantees for a rough
 * surface with porosity; weighting by 1 - E_s makes the bound hold by
 * construction, and light removed from the specular by the pores
 * (1 - a G_p) flows into the diffuse, as in Merillou's model. */

#define SOAK_POROUS_GGX_TABLE 64

typedef struct soak_porous_ggx_params {
    double albedo;          /* diffuse albedo of the material, [0,1] */
    double roughness;       /* GGX alpha of the material, [SOAK_GGX_ALPHA_MIN, 1] */
    double eta;             /* material index / air, [1, 3]; 1 = no specular */
    double porosity;        /* [0,1] */
    double sp;              /* pore depth / diameter, [0, SOAK_POROUS_SP_MAX] */
    double water_roughness; /* GGX alpha of the water in the pores, [SOAK_GGX_ALPHA_MIN, 1] */
    double eta_water;       /* [1, 3], 1.33 for water */
} soak_porous_ggx_params;

/* Setup result ("closure"): parameters plus specular-albedo tables on a
 * cos grid (crowded towards grazing, down to cos = 1e-6). The tables depend
 * only on roughness, eta, water_roughness and eta_water; r_wall also on
 * albedo. */
typedef struct soak_porous_ggx {
    soak_porous_ggx_params p;
    double mu[SOAK_POROUS_GGX_TABLE];     /* table nodes, cos(theta_i) */
    double e_mat[SOAK_POROUS_GGX_TABLE];  /* albedo of f_mat */
    double e_gmat[SOAK_POROUS_GGX_TABLE]; /* albedo of G_p f_mat */
    double e_gwat[SOAK_POROUS_GGX_TABLE]; /* albedo of G_p f_water */
    double avg_mat, avg_gmat, avg_gwat;   /* their cosine-weighted averages */
    double r_wall;                        /* r above */
} soak_porous_ggx;

soak_status soak_porous_ggx_validate(const soak_porous_ggx_params *p);
/* ~3e5 GGX evaluations (~30 ms): once per material, not per shading point. */
soak_status soak_porous_ggx_setup(const soak_porous_ggx_params *p, soak_porous_ggx *c);
soak_status soak_porous_ggx_eval(const soak_porous_ggx *c, double fill, soak_vec3 wi, soak_vec3 wo, double *f);
/* Importance sampling: a one-sample mixture of the GGX visible-normal
 * sampler of each specular lobe and a cosine lobe, picked by u_lobe in
 * proportion to the lobes' albedo at wi. Writes wo, f = eval(wi, wo) and the
 * mixture density pdf (solid angle of wo; soak_porous_ggx_pdf gives the same
 * value). A sample that ends below the horizon, or a grazing pair whose GGX
 * terms overflow (both cosines ~1e-300, soak/ggx.h), has f = pdf = 0 ("no sample").
 * u_lobe, u1, u2 in [0,1]. */
soak_status soak_porous_ggx_sample(const soak_porous_ggx *c, double fill, soak_vec3 wi, double u_lobe, double u1,
                                   double u2, soak_vec3 *wo, double *f, double *pdf);
soak_status soak_porous_ggx_pdf(const soak_porous_ggx *c, double fill, soak_vec3 wi, soak_vec3 wo, double *pdf);
/* Tabulated directional albedo of the glossy (specular) terms at cos_i for
 * this fill; the diffuse directional albedo is at most (1 - this) * max rho_eff. */
soak_status soak_porous_ggx_spec_albedo(const soak_porous_ggx *c, double fill, double cos_i, double *E);
/* White-sky albedo of the diffuse term D at this fill and the darkening
 * factor albedo(fill) / albedo(0) (1 when albedo(0) == 0). Outputs may be NULL. */
soak_status soak_porous_ggx_albedo_factor(const soak_porous_ggx *c, double fill, double *diffuse_albedo,
                                          double *factor);

#endif
