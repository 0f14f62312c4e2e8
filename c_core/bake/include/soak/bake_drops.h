/* Rain over time: drop impacts that wet a surface (`soak bake drops`).
 *
 * Drop-size distribution: J. S. Marshall, W. McK. Palmer, "The distribution
 * of raindrops with size", J. Meteorology 5, 165-166, 1948:
 *   N(D) = N0 exp(-Lambda D),  N0 = 0.08 cm^-4 = 8000 m^-3 mm^-1,
 *   Lambda = 41 R^-0.21 cm^-1 = 4.1 R^-0.21 mm^-1  (R rain rate in mm/h).
 * Terminal velocity: D. Atlas, R. C. Srivastava, R. S. Sekhon, "Doppler
 * radar characteristics of precipitation at vertical incidence", Rev.
 * Geophys. Space Phys. 11(1), 1-35, 1973, their fit to Gunn & Kinzer (1949):
 *   v(D) = 9.65 - 10.3 exp(-0.6 D) m/s, D in mm.
 * The fit is negative below D0 = ln(10.3 / 9.65) / 0.6 = 0.1087 mm: we take
 * v = max(0, fit), so those drops never land. Drops above SOAK_DROP_D_MAX_MM
 * break up in free fall (Pruppacher & Klett, "Microphysics of Clouds and
 * Precipitation", 1997, sec. 10.3.6); the distribution is cut there.
 * Impacts per horizontal area and time: n = int N(D) v(D) dD (closed form,
 * soak_drop_flux). MP with Atlas' v carries 1.08-1.18 R of water for R in
 * 1..50 mm/h, not exactly R (the two fits come from different data sets);
 * drop volumes are kept physical, the mismatch is stated, not hidden.
 *
 * Spread on impact: C. Clanet, C. Beguin, D. Richard, D. Quere, "Maximal
 * deformation of an impacting drop", J. Fluid Mech. 517, 199-208, 2004:
 *   d_max / D = 0.9 We^(1/4),  We = rho v^2 D / sigma,
 * water at 20 C (rho 998.2 kg/m^3, sigma 0.0728 N/m); we never let a splat
 * be narrower than its drop (factor >= 1; the law is for We >> 1). */
#ifndef SOAK_BAKE_DROPS_H
#define SOAK_BAKE_DROPS_H

#include <stddef.h>
#include <stdint.h>

#include "soak/bake.h"
#include "soak/image.h"
#include "soak/status.h"

#define SOAK_DROP_N0 8000.0        /* m^-3 mm^-1 */
#define SOAK_DROP_D_MAX_MM 6.0     /* largest drop, mm */
#define SOAK_DROP_RATE_MAX 500.0   /* mm/h accepted */
#define SOAK_WATER_RHO 998.2       /* kg/m^3, 20 C */
#define SOAK_WATER_SIGMA 0.0728    /* N/m, 20 C */
#define SOAK_GRAVITY 9.80665       /* m/s^2 */

/* Lambda (1/mm) for rate R (mm/h) > 0. */
double soak_mp_lambda(double rate_mm_h);
/* N(D), m^-3 mm^-1; 0 for R <= 0 or D outside [0, D_MAX]. */
double soak_mp_density(double d_mm, double rate_mm_h);
/* Atlas et al. terminal velocity, m/s, clamped at 0. */
double soak_drop_velocity(double d_mm);
/* Impacts per m^2 per s of drops with d_lo <= D <= d_hi (mm) at rate R,
 * closed form of int N v dD; 0 for R = 0. NaN never: bad input gives 0. */
double soak_drop_flux(double rate_mm_h, double d_lo_mm, double d_hi_mm);
/* Clanet et al. spread factor d_max / D (>= 1) of a drop of D mm at its
 * terminal velocity. */
double soak_drop_spread_factor(double d_mm);
/* A diameter (mm) drawn from the impact distribution N(D) v(D) on
 * [d_lo, D_MAX] by rejection from the truncated exponential; u() returns
 * uniform [0, 1) numbers from ctx. */
typedef double (*soak_uniform_fn)(void *ctx);
double soak_drop_sample(double rate_mm_h, double d_lo_mm, soak_uniform_fn u, void *ctx);

/* ---- drops bake (bake_drops.c) ------------------------------------------
 * Impacts are a space-time Poisson process of rate n E(x) per unit area
 * (E the sky exposure, 1 without a map), drawn per cell of
 * SOAK_DROPS_CELL x SOAK_DROPS_CELL texels and SOAK_DROPS_SLAB seconds from
 * a random stream of (seed, slab, cell) and thinned by E / max(E, 1), so a
 * frame's impacts depend on nothing but the seed and the parameters. Each
 * impact spreads its volume pi D^3 / 6 evenly over the texels whose centres
 * lie in its spread disc (the texel under its centre when none does),
 * adding depth until the texel holds `capacity` (the excess runs off).
 * Impacts are applied in time order (cell and index break ties), every
 * texel by one thread, so any thread count and any frame range give the
 * same bits. Wet-map value w = depth / capacity in [0, 1]: the volume
 * fraction of the wetness chain (soak/wetness.h step 2), whose pore filling
 * turns it into pore fill and film. After `duration` the map at the rain's
 * end dries by the drying bake's pore schedule (soak_bake_drying,
 * threshold 0, its time = (t - duration) / dry_time) times that map. */
#define SOAK_DROPS_CELL 32
#define SOAK_DROPS_SLAB 0.0625 /* s */
#define SOAK_DROPS_MAX_TIME 1e6
#define SOAK_DROPS_MAX_SCALE 100.0 /* m per texel */

typedef struct soak_drops_params {
    uint64_t seed;
    double rate_mm_h;       /* [0, 500] */
    double texel_m;         /* metres per texel, (0, 100] */
    double capacity_m;      /* water depth of a full wet map, (0, 1] m */
    double spread_factor;   /* 0 = Clanet et al. per drop; else fixed d/D in [1, 100] */
    double min_diameter_mm; /* smallest drop drawn, [0, D_MAX) (0 = all that land) */
    double duration;        /* s of rain, [0, 1e6] */
    double dry_time;        /* s for the drying schedule's [0, 1], (0, 1e6] */
    double t_fill;          /* drying schedule's pore emptying time, [0, 1] */
    int wrap;               /* 1: splats wrap across the map's edges (a tiling plane); 0: clipped */
    int splash;             /* 1: drops on wet texels splash (below); 0: every drop is one splat */
    double splash_fraction; /* share of a splashing drop's volume thrown as secondaries, [0, 1] */
    double splash_speed;    /* secondaries' largest launch speed / impact speed, [0, 1] */
} soak_drops_params;

/* seed 0, 10 mm/h, 1 mm texels, capacity 0.2 mm, Clanet spread, all drops,
 * 10 s of rain, 20 s drying, t_fill 0.2, wrapping, no splashes (fraction
 * 0.2, speed 0.2 when turned on). */
void soak_drops_defaults(soak_drops_params *p);
soak_status soak_drops_check(const soak_drops_params *p);

typedef struct soak_drop_impact {
    double x, y;    /* texels from the top-left corner (texel i covers [i, i + 1)) */
    double t;       /* s */
    double d_mm;    /* drop diameter */
    uint32_t cell;  /* tie break: cell index, then draw index */
    uint32_t index;
} soak_drop_impact;

/* Impacts with slab index in [slab0, slab1) over a width x height map,
 * sorted by (t, cell, index); *out is malloc'ed (free it), NULL when none.
 * exposure: NULL or a 1-channel width x height map of finite values >= 0. */
soak_status soak_drops_impacts(const soak_drops_params *p, const soak_image *exposure, int width, int height,
                               long slab0, long slab1, soak_drop_impact **out, size_t *count);

typedef struct soak_drops_state soak_drops_state;

/* A dry surface at t = 0. exposure as above (copied). */
soak_status soak_drops_create(const soak_drops_params *p, const soak_image *exposure, int width, int height,
                              soak_drops_state **out);
void soak_drops_destroy(soak_drops_state *s);
/* Wet map at time t >= 0 (1 channel, allocated here). Times may come in any
 * order; going back replays from t = 0. */
soak_status soak_drops_frame(soak_drops_state *s, double t, const soak_bake_exec *exec, soak_image *out);
/* Impacts applied so far (every impact with t_i < the last frame's time). */
size_t soak_drops_applied(const soak_drops_state *s);
/* Of those, the impacts that splashed. */
size_t soak_drops_splashed(const soak_drops_state *s);

/* ---- splashes (bake_drops_splash.c) -------------------------------------
 * A drop landing on a texel that holds water (depth h > 0) splashes when
 * K = We Oh^(-0.4) exceeds the crown-splash threshold of a drop on a
 * liquid film, G. E. Cossali, A. Coghe, M. Marengo, "The impact of a single
 * drop on a wetted solid surface", Exp. Fluids 22, 463-472 (1997):
 *   K_c = 2100 + 5880 delta^1.44,  delta = h / D (clamped to [0, 1]),
 * We = rho v^2 D / sigma, Oh = mu / sqrt(rho sigma D), water at 20 C. (On a
 * dry solid Mundo, Sommerfeld & Tropea 1995, Int. J. Multiphase Flow 21,
 * 151-173, put the threshold at Oh Re^1.25 = 57.7; Oh Re^1.25 = (We
 * Oh^-0.4)^0.625 exactly, so that is K = 57.7^1.6 = 657, not 57.7. Dry
 * texels are not splashed here.) The crown breaks into N fingers, N =
 * We^1/2 Re^1/4 / (4 sqrt 3) (Marmanis & Thoroddsen, "Scaling of the
 * fingering pattern of an impacting drop", Phys. Fluids 8, 1344-1346,
 * 1996), rounded, at least 1; each throws one secondary drop, at equal
 * angles with a random phase, of equal volume: splash_fraction of the
 * drop's volume in all (an assumed share, a setting: no measurement of it
 * for rain on a film is used), the rest spreading as the drop's splat.
 * A secondary leaves at 45 deg with a speed uniform in [1/2, 1] of
 * splash_speed times the impact speed (assumed) and lands ballistically at
 * r = u^2 / g; it spreads by Clanet's factor at its own Weber number. */

/* K = We Oh^-0.4 of a drop of d_mm at speed v (m/s); 0 for bad input. */
double soak_splash_k(double d_mm, double v);
/* Cossali et al.'s threshold K_c for a film of film_m metres under a drop
 * of d_mm; NaN-free (bad input gives the film-free 2100). */
double soak_splash_k_critical(double film_m, double d_mm);
/* Marmanis & Thoroddsen's finger count, >= 1. */
int soak_splash_fingers(double d_mm, double v);

#define SOAK_SPLASH_MAX_FINGERS 256

/* One secondary drop: landing point (texels), diameter (mm), speed (m/s). */
typedef struct soak_splash_drop {
    double x, y, d_mm, v;
} soak_splash_drop;

/* The secondaries of impact imp on a texel holding film_m of water:
 * returns their count n (0: no splash) into out[SOAK_SPLASH_MAX_FINGERS];
 * their volumes sum to splash_fraction of the drop's. Deterministic in
 * (seed, impact). */
int soak_splash_throw(const soak_drops_params *p, const soak_drop_impact *imp, double film_m,
                      soak_splash_drop out[SOAK_SPLASH_MAX_FINGERS]);

#endif
