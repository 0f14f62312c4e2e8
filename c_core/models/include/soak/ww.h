/* Weidlich-Wilkie layered BRDF with a smooth water film on top of a GGX base,
 * and the Tri-Ace fast paths for it.
 * Sources: A. Weidlich, A. Wilkie, "Arbitrarily Layered Micro-Facet
 * Surfaces", GRAPHITE 2007; [Lag13] (Lagarde 2013), "Realtime double layer
 * material" and its RenderMonkey code; Tri-Ace approximations as reported in
 * [Lag13] ("Refract vector", "Fresnel term", "Absorption term"), after
 * Y. Gotanda (tri-Ace), "Beyond a Simple Physically Based Blinn-Phong Model".
 *
 * Exact model (soak_ww_eval). Air (index 1) above a flat, smooth water film
 * of index n = n_water over an opaque base. Directions are unit vectors in the
 * local frame, normal +z, both in the upper hemisphere. Inside the water,
 * wi' and wo' are the Snell-refracted directions through the flat film
 * (tangential part scaled by 1/n; refraction about the macro normal, which is
 * the only consistent choice for a mirror-flat top -- WW's code and [Lag13]
 * refract about the half vector, a heuristic for rough top layers).
 *   f(wi, wo) = T12(cos_i) * f_base(wi', wo') * a * T21(cos_o') / n^2
 *   a = exp(-alpha_abs * d * (1/cos_i' + 1/cos_o'))
 * plus a delta (mirror) lobe of weight F12(cos_i) (soak_ww_specular).
 * Corrections and choices, each tested:
 *  - [Lag13] prints a = e^{alpha d (1/theta_i' 1/theta_r')}: the exponent
 *    needs a minus sign, the two path lengths add ('+'), and they are
 *    d / cos(theta') (cosines, not angles).
 *  - The 1/n^2 factor: radiance crossing a smooth interface from index n_a
 *    into n_b is multiplied by T (n_b/n_a)^2, since L/n^2 is invariant
 *    (equivalently, etendue n^2 cos dw is conserved: cos_o dw_o =
 *    n^2 cos_o' dw_o'). Irradiance E on top delivers flux T12 E to the base;
 *    the base's radiance L' = f_base T12 E a, leaving through the film as
 *    L = T21 L' / n^2. WW 2007 and [Lag13] omit the 1/n^2; without it a
 *    glossy base whose lobe fits inside the escape cone returns up to
 *    n^2 T12 T21 ~ 1.7 of the incident energy. With it the directional albedo
 *    is T12 * int_{cone} f_base a T21 cos' dw' <= T12 * albedo_base <= 1 - F12.
 *  - Reciprocity: Fresnel reflectance is the same on both sides of an
 *    interface for Snell-paired angles, so T12(cos_i) = T21(cos_i') and
 *    f = T21(cos_i') T21(cos_o') f_base a / n^2 is symmetric.
 *  - WW's t = 1 - F21 G ([Lag13]) becomes T21 for the smooth film (G = 1).
 *  - Interreflections between the base and the underside of the film are
 *    omitted, as in WW (soak/film.h has them for a Lambertian base); light
 *    reflected back down by the film is lost, so energy stays <= 1.
 *  - n_water == 1: no interface, T = 1, wi' = wi; f equals the base BRDF
 *    (times a, which is 1 for zero thickness).
 *
 * Base (evaluated inside the water, indices relative to water):
 *  - SOAK_WW_DIELECTRIC: GGX Cook-Torrance with eta = n_base / n_water plus a
 *    Lambertian term kd/pi weighted by the Fresnel transmissions of the base
 *    interface at the macro normal, (1 - F23(cos_i'))(1 - F23(cos_o')): the
 *    WW layering rule applied once more to a diffuse sub-layer (reciprocal;
 *    keeps the base albedo <= 1 for kd <= 1, verified by quadrature).
 *  - SOAK_WW_CONDUCTOR: GGX Cook-Torrance with complex index
 *    (n_base + i k_base) / n_water, no diffuse term.
 * All per colour channel: for RGB call once per channel (soak_ww_copper gives
 * [Lag13]'s copper constants). */
#ifndef SOAK_WW_H
#define SOAK_WW_H

#include "soak/status.h"
#include "soak/vec.h"

#define SOAK_WW_N_WATER 1.33
#define SOAK_WW_N_WATER_MIN 1.0
#define SOAK_WW_N_WATER_MAX 3.0
#define SOAK_WW_ABSORPTION_MAX 1e6 /* per length unit */
#define SOAK_WW_THICKNESS_MAX 1e3  /* same length unit as 1/absorption */
#define SOAK_WW_N_DIELECTRIC_MIN 1.0
#define SOAK_WW_N_DIELECTRIC_MAX 3.0
#define SOAK_WW_N_CONDUCTOR_MIN 0.01
#define SOAK_WW_N_CONDUCTOR_MAX 100.0
#define SOAK_WW_K_MAX 100.0

typedef enum soak_ww_base {
    SOAK_WW_DIELECTRIC = 0,
    SOAK_WW_CONDUCTOR = 1
} soak_ww_base;

typedef struct soak_ww {
    soak_ww_base base;
    double n_water;    /* film index relative to air, [1, 3]; 1 = no interface */
    double absorption; /* Beer-Lambert coefficient of the water, [0, 1e6] per length unit */
    double thickness;  /* film thickness, [0, 1e3] in that length unit; 0 = no absorption */
    double alpha;      /* GGX roughness of the base, [1e-4, 1] (soak/ggx.h) */
    double n_base;     /* base index relative to air: dielectric [1, 3], conductor [0.01, 100] */
    double k_base;     /* conductor extinction relative to air, [0, 100]; ignored (but must be
                          finite) for dielectric */
    double kd;         /* dielectric diffuse albedo, [0, 1]; ignored (but must be finite) for conductor */
} soak_ww;

/* Defaults: water 1.33 without absorption, dielectric base n 1.5, alpha 0.3, kd 0.5. */
void soak_ww_default(soak_ww *m);
soak_status soak_ww_validate(const soak_ww *m);

/* [Lag13]'s copper, index relative to vacuum, per RGB channel:
 * n = (3.406149, 2.161600, 1.504326), k = (5.225178, 3.756258, 3.018729). */
void soak_ww_copper(soak_rgb *n, soak_rgb *k);

/* Non-delta BRDF f(wi, wo) in 1/sr (no cosine). */
soak_status soak_ww_eval(const soak_ww *m, soak_vec3 wi, soak_vec3 wo, double *f);

/* Reflectance of the delta (mirror) lobe of the film, F12(cos_i), cos_i in [0, 1]. */
soak_status soak_ww_specular(const soak_ww *m, double cos_i, double *R);

/* The base BRDF alone, seen from inside the water (indices relative to the
 * water), for directions wi', wo' in the water. */
soak_status soak_ww_base_eval(const soak_ww *m, soak_vec3 wi_water, soak_vec3 wo_water, double *f);

/* Sampling for a path tracer. Given wo (toward the viewer) and u0, u1, u2 in
 * [0, 1]: with probability F12(cos_o) the mirror direction (*is_delta = 1,
 * *weight = 1, *pdf = 0); otherwise a direction wi from the refracted base
 * lobe (GGX visible normals or cosine for the diffuse part, chosen by u0
 * within the remaining range), *weight = f cos_i / pdf_total where pdf_total
 * includes the (1 - F12) selection probability. A sampled direction that
 * cannot leave the film (total internal reflection) or points below the base
 * horizon returns *weight = 0 (the path ends; that energy is lost, as in the
 * model). */
soak_status soak_ww_sample(const soak_ww *m, soak_vec3 wo, double u0, double u1, double u2, soak_vec3 *wi,
                           double *weight, double *pdf, int *is_delta);

/* ---- Tri-Ace fast paths (ww_triace.c) ----
 * Accuracy against the exact model is measured in tests/c/models/test_ww.c. */

/* [Lag13] / Tri-Ace: F_bottom(n2, n3) = F0(n2, n3) (1 - F0(n2, 1)), the
 * normal-incidence value of (1 - F21) F23. n2: film index, n3: base index,
 * both relative to air; [SOAK_ETA_MIN, SOAK_ETA_MAX]. */
soak_status soak_triace_fbottom_dielectric(double n2, double n3, double *F);
/* [Lag13]'s conductor extension: ((n3-n2)^2 + k3^2) / ((n3+n2)^2 + k3^2) (1 - F0(n2, 1)). */
soak_status soak_triace_fbottom_conductor(double n2, double n3, double k3, double *F);

/* Linear absorption a ~ max(0, 1 - alpha' (1/cos_l + 1/cos_v)), the first-order
 * Taylor form of exp(-alpha' (1/cos_l + 1/cos_v)) with alpha' = alpha_abs d.
 * [Lag13] prints '1/N.L 1/N.V' (a product); the path lengths add, so it is
 * the sum. cos in (0, 1], alpha' in [0, 1e9]. */
soak_status soak_triace_absorption_linear(double alpha_prime, double cos_l, double cos_v, double *a);

/* Polynomial refraction for eta = 1/1.33 (air into water), [Lag13]:
 *   t = i / 1.33 + (c0 + c1 cos_i + c2 cos_i^2) n,  cos_i = -i.n,
 * (c0, c1, c2) = (-0.666308423880957, 0.7518796992481197, -0.34853799144237796)
 * fitted to (eta cos_i - cos_t). i: unit incident direction (toward the
 * surface), n: unit normal on the incident side (i.n <= 0). t points into the
 * water and is NOT unit length (|t| within about 1.5% of 1). */
soak_status soak_refract_1_33(soak_vec3 i, soak_vec3 n, soak_vec3 *t);

/* Precomputed constants of the fast evaluation. */
typedef struct soak_ww_triace {
    double r0_top;       /* F0(1, n_water) for Schlick's T12 */
    double fbottom;      /* specular F_bottom */
    double diffuse;      /* kd/pi (1 - F0(n2,1)) (1 - F0(n2,n3))^2, 0 for conductors */
    double alpha2;       /* GGX alpha^2 */
    double alpha_prime;  /* absorption * thickness */
    double inv_n2;       /* 1 / n_water^2, radiance compression */
} soak_ww_triace;

/* Accepts the liquid's index n_water in [SOAK_WW_TRIACE_N_MIN,
 * SOAK_WW_TRIACE_N_MAX] (water 1.333, and the shipped coffee, cola, wine);
 * others return SOAK_ERR_ARG. The Fresnel terms (r0_top, fbottom, diffuse)
 * and inv_n2 use n_water; the refraction polynomial is [Lag13]'s fit for
 * 1.33 at every accepted index. Its error (tests/c/models/test_ww.c, printed table):
 * at n_water = 1.333 the fast path equals the exact model at normal
 * incidence without absorption, and its largest relative error over the
 * 0..85 degree grid (already above 1 at grazing for n = 1.33) rises by at
 * most 0.02, over theta <= 60 degrees by at most 0.005 (measured: 0.054-0.225
 * at 1.33 -> within +0.004 at 1.333). */
#define SOAK_WW_TRIACE_N_MIN 1.30
#define SOAK_WW_TRIACE_N_MAX 1.36
soak_status soak_ww_triace_setup(const soak_ww *m, soak_ww_triace *fast);

/* Fast WW: f ~ (1 - F12_Schlick(cos_i)) a_lin / n^2 *
 *   [F_bottom D(h') G2/(4 cos_i' cos_o') + diffuse],
 * with wi', wo' from soak_refract_1_33 (renormalised) and a_lin evaluated
 * with the refracted cosines (>= 0.66, so 1/cos is bounded; with the
 * unrefracted N.L, N.V [Lag13] shows the linear form fails at grazing).
 * No pow/exp; equals soak_ww_eval exactly at normal incidence without
 * absorption. Not reciprocal: Schlick T12 at cos_i but a constant exit
 * transmission (1 - F0(1.33, 1)) inside F_bottom, which is the dominant
 * error at grazing theta_o (see tests/c/models/test_ww.c table). Everything else is
 * symmetric, so f(wi, wo) / f(wo, wi) = S(cos_i) / S(cos_o) exactly,
 * S(c) = 1 - (1 - c)^5. Measured (tests/c/models/test_stability.c, 2e5 pairs
 * uniform in solid angle, both polar angles <= 85 deg): 78 % of pairs
 * are more than 1 % off; the largest ratio is 1 / S(cos 85 deg) = 2.731.
 * Over the whole hemisphere the ratio is unbounded (S(0) = 0: f(wo, wi)
 * vanishes for a grazing wo where f(wi, wo) does not). */
soak_status soak_ww_eval_triace(const soak_ww_triace *fast, soak_vec3 wi, soak_vec3 wo, double *f);
/* Unchecked form for hot loops: fast from soak_ww_triace_setup, wi.z > 0, wo.z > 0, unit. */
double soak_ww_eval_triace_raw(const soak_ww_triace *fast, soak_vec3 wi, soak_vec3 wo);

#endif
