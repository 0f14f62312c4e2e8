/* Wetness -> material parameters: the ONE mapping every front end uses.
 * Front ends (path tracer, POV-Ray, Blender) never re-derive this physics:
 * they call soak_wetness_eval, or read the table soak_wetness_table /
 * soak_wetness_export_json produce (`soak materials --json --table N`) and
 * interpolate linearly in w between its rows.
 *
 * Formula chain (per colour channel where it applies):
 *
 * 1. Schedule (Hnat et al. 2006, [Hnat06] sec. 3.3.2, Delta t table): a point
 *    whose wet-map start time is t0 receives liquid over the pore fill time
 *    t_fill:  progress P = clamp((t - t0) / t_fill, 0, 1); with t_fill = 0
 *    the step P = (t >= t0 ? 1 : 0) ([Hnat06]: "straight border"). One
 *    owner: soak_fill_fraction (soak/porous.h), right-continuous in t.
 *    Delivered liquid L = w * P, w in [0,1] the wetness (wet-map amount).
 *
 * 2. Saturation point. w is read as the volume fraction of liquid in the
 *    surface layer, so the pores are full at L = w_sat = porosity (open
 *    porosity alpha of [Lag13]/[Hnat06]); non-porous kinds have w_sat = 0.
 *      pore fill        f = min(L / w_sat, 1)              (0 if w_sat = 0)
 *      film coverage    c = max(L - w_sat, 0) / (1 - w_sat)
 *    Below saturation there is no film; above it, the excess liquid lies on
 *    top as a film of the given thickness over the area fraction c
 *    (Lagarde, [Lag13]: "when pores are filled ... water propagates onto
 *    the material as a thin layer"). The coverage form keeps every output
 *    continuous in w.
 *
 * 3. Phase function and medium (Jensen et al. 1999, [JLD99] sec. 3.2/4):
 *    each of g1, g2, w_lobe is lerped dry -> wet by f; g = mean cosine
 *    w_lobe g1 + (1 - w_lobe) g2. The liquid occupies the volume fraction
 *    porosity * f, and its coefficients add (Beer-Lambert for a mixture):
 *      sigma_s = omega_dry sigma_t + porosity f sigma_s,liquid
 *      sigma_a = (1 - omega_dry) sigma_t + porosity f sigma_a,liquid
 *    ([JLD99]'s cognac: a coloured liquid modulates sigma_s and sigma_a; a
 *    clear one leaves them practically unchanged).
 *
 * 4. Subsurface albedo (van de Hulst 1980, soak/vdhulst.h):
 *      omega_dry = inverse of R(omega, g_dry) at the dry albedo (on load),
 *      omega     = sigma_s / (sigma_s + sigma_a)         (= omega_dry at f=0),
 *      albedo_subsurface = R(omega, g(f)).
 *    The phase change is the grains' index matching only (Twomey, Bohren &
 *    Mergenthaler 1986: liquid instead of air around the grains makes their
 *    scattering more forward); plus the liquid's own absorption. The
 *    liquid-air interface is NOT in this step (step 5). Conductors: no
 *    subsurface, unchanged.
 *
 * 5. Liquid-air interface (Lekner & Dorf 1988, soak/film.h): the darkening
 *    by total internal reflection happens wherever liquid meets air, whether
 *    the liquid fills the pores or lies on top -- once per unit area:
 *      pore water: area fraction a = porosity f (the pores' share of the
 *        surface, as step 6's water specular), zero thickness;
 *      film: coverage c, thickness h; where the film lies it REPLACES the
 *        pore water's surface (one interface, one TIR).
 *    With T_h(A) = soak_film_albedo_diffuse (index n_liquid, absorption
 *    sigma_a,liquid, thickness h) for dielectrics,
 *      albedo_film  = T_h(A) - T_h(0)   (A = albedo_subsurface; T_h(0) is the
 *                                        interface's own specular part S_h)
 *      open         = (1 - a) A + a (T_0(A) - T_0(0))
 *      open_total   = (1 - a) A + a T_0(A)
 *    conductors: normal incidence, incoherent sum over the film,
 *      albedo_film = (1 - R12)^2 R23 e / (1 - R12 R23 e), e = exp(-2 sigma_a h),
 *      R12 = F0(n_liquid), R23 = F0(n / n_liquid, k / n_liquid); open = A.
 *      albedo       = (1 - c) open       + c albedo_film
 *      albedo_total = (1 - c) open_total + c (albedo_film + S_h)
 *    albedo is what a renderer puts under a separate, non-compensating film
 *    (clear-coat) lobe of index n_liquid with weight c, plus step 6's water
 *    specular for the pore water; albedo_total is the hemispherical
 *    reflectance a measurement would give (without the material's own dry
 *    specular lobe).
 *    Why: the chain used to model no interface over saturated pores and
 *    then stacked the film's TIR on a phase change whose wet values
 *    ([JLD99]) were eyeballed to the WHOLE darkening -- interface included
 *    -- so the interface darkening counted twice (wet/dry 0.23-0.39). The
 *    wet phase values are now calibrated against measured wet/dry ratios
 *    with the interface modelled here (docs/calibration.md).
 *
 * 6. Roughness and specular weights: GGX alpha lerps dry -> wet by f (pores
 *    filled with a flat liquid surface); Merillou/Hnat ([Hnat06] Eq. 3) at
 *    G_p = 1: the material's specular weight is 1 - porosity, the water in
 *    the pores adds a mirror-like specular of weight porosity * f. Front ends
 *    evaluating G_p multiply porosity by it. Hnat's removal of the pores'
 *    diffuse contribution (Eq. 2) is NOT applied: step 4 already darkens,
 *    and applying both would count the same effect twice. The reference
 *    tracer renders this interface: a preset's surface is soak/bsdf.h
 *    COATED (GGX of width ggx_alpha at the preset's index, weight
 *    specular_weight, over the Lambertian body of albedo_subsurface; under
 *    the film its index is n / n_liquid; the pore water lies over the body
 *    alone and the grains outside the film keep the lobe in air,
 *    soak/wet_specular.h point 4), traced facet by facet by
 *    `soak measure --config coated` as a second method.
 *
 * Limitations: the semi-infinite formula is used for thin sheets too (their
 * front-lit albedo; translucency needs a volumetric renderer with sigma_s,
 * sigma_a, phase and thickness_m); the film is flat and non-scattering.
 *
 * Units: every length here is in metres and every coefficient in 1/m
 * (fields named _m, _per_m), as in soak_preset; the files' mm and 1/mm are
 * converted where they are read and written (soak/units.h). */
#ifndef SOAK_WETNESS_H
#define SOAK_WETNESS_H

#include "soak/hg.h"
#include "soak/preset.h"
#include "soak/status.h"
#include "soak/vec.h"

#define SOAK_WET_TIME_MAX 1e9       /* |t|, |t0| and t_fill bound */
#define SOAK_WET_FILM_MAX_M 1.0     /* film thickness bound, m */
#define SOAK_WET_TABLE_MAX 4097     /* rows of a wetness table */

typedef struct soak_wet_input {
    double wetness;          /* w in [0,1] */
    double time;             /* t, same units as t_fill */
    double t0;               /* wet-map start time */
    double t_fill;           /* pore fill time >= 0; 0 = instant */
    double film_thickness_m; /* film thickness where a film lies, [0, 1] m */
} soak_wet_input;

typedef struct soak_wet_params {
    double wetness;          /* input w */
    double progress;         /* schedule P in [0,1] */
    double liquid;           /* delivered liquid L = w P */
    double saturation;       /* w_sat */
    double fill;             /* pore fill fraction f in [0,1] */
    double film_coverage;    /* c in [0,1] */
    int film;                /* c > 0 */
    double film_thickness_m; /* thickness of the film where present */
    double film_ior;         /* n_liquid */
    soak_rgb film_absorption_per_m; /* the liquid's sigma_a */

    soak_rgb albedo_subsurface; /* step 4 */
    soak_rgb albedo_film;       /* step 5, at full coverage */
    soak_rgb albedo;            /* coverage-weighted diffuse albedo */
    soak_rgb albedo_total;      /* coverage-weighted total reflectance */

    double ggx_alpha;
    soak_hg2 phase;             /* zero for conductors */
    double mean_cosine;
    soak_rgb omega;             /* single-scattering albedo; zero for conductors */
    soak_rgb sigma_s_per_m;
    soak_rgb sigma_a_per_m;

    double specular_weight;       /* material's own specular, 1 - porosity */
    double water_specular_weight; /* porosity * f */
} soak_wet_params;

/* Steady state for a preset: t = 1, t0 = 0, t_fill = 0 (progress 1),
 * film thickness = the preset's default. */
soak_wet_input soak_wet_input_steady(const soak_preset *preset, double wetness);

/* The mapping. All inputs validated (SOAK_ERR_NULL / SOAK_ERR_ARG); out is
 * written only on SOAK_OK and is free of NaN/Inf. */
soak_status soak_wetness_eval(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_input *in,
                              soak_wet_params *out);

/* Directional-hemispherical reflectance under a sun: collimated light at
 * cos_i = cos(zenith angle) in [0, 1], for the state w that
 * soak_wetness_eval returned for (preset, liquid). Step 5 with the
 * interface's directional transmission (soak_film_albedo_dir) in place of
 * the diffuse one; the subsurface body stays Lambertian (step 4's albedo is
 * van de Hulst's, direction-free) and conductors keep step 5's normal-
 * incidence model. albedo: without the liquid's mirror reflection (what a
 * camera away from the mirror direction sees); albedo_total: with it (what
 * a pyranometer sees). Field albedos are measured under the sun: compare
 * them with these, not with w->albedo_total (uniform diffuse light). */
soak_status soak_wetness_albedo_sun(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_params *w,
                                    double cos_i, soak_rgb *albedo, soak_rgb *albedo_total);

/* The view factor: how the diffuse colour seen along a view direction at
 * cos_o = cos(view zenith) in [0, 1] differs from the hemispherical albedo,
 * under uniform diffuse light. By reciprocity that radiance factor is the
 * directional-hemispherical albedo at cos_o (soak_wetness_albedo_sun's
 * albedo, without the mirror), so factor = albedo_sun(cos_o) / albedo per
 * channel (1 where the albedo is 0). Its cosine-weighted mean over the
 * hemisphere is 1; 1 everywhere when dry (no interface) and for conductors
 * (normal-incidence model). A front end whose diffuse colour cannot follow
 * the light's angle can still follow the viewer's: colour x factor removes
 * the out-going half of the interface's angular transmission. */
soak_status soak_wetness_view_factor(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_params *w,
                                     double cos_o, soak_rgb *factor);

/* The wet/dry ratio a measurement of preset->measured group would see at
 * wetness w: the preset re-based on the sample's grey dry albedo, evaluated
 * in steady state and under the measurement's light (a sun at
 * measured_sun_zenith_deg, else uniform diffuse light), green channel,
 * measured_total choosing albedo_total or albedo. SOAK_ERR_ARG without a
 * measured group. */
soak_status soak_wetness_measured_ratio(const soak_preset *preset, const soak_liquid *liquid, double wetness,
                                        double *ratio);

/* Share of the surface where the liquid meets the air: the film's coverage c
 * plus the uncovered liquid-filled pores, c + (1 - c) porosity f (zero pore
 * share for conductors). Front ends weight the liquid's Fresnel mirror with
 * it; in [0, 1], 0 for a NULL argument. */
double soak_wet_interface_area(const soak_wet_params *w);

/* n >= 2 rows at w_i = i / (n - 1), steady state, film thickness
 * film_thickness_m (< 0: the preset's default). Row i equals
 * soak_wetness_eval at that w exactly. */
soak_status soak_wetness_table(const soak_preset *preset, const soak_liquid *liquid, int n, double film_thickness_m,
                               soak_wet_params *rows);

/* JSON for front ends: every preset and liquid with all fields, derived
 * sigma_s/sigma_a, and (table_n >= 2) a wetness table per preset for
 * `liquid_name` (NULL: "water"); table_n = 0: no table. *json is malloc'd,
 * free() it. */
soak_status soak_wetness_export_json(const soak_preset_db *db, const char *liquid_name, int table_n, char **json);

#endif
