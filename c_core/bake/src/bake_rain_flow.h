/* Downhill flow of the rain bake (soak/bake_rain.h, step 3), private to the
 * bake layer and exposed to white-box tests.
 *
 * One routing sweep is a Jacobi update: every texel's outflows are computed
 * from the depths before the sweep, then every texel's depth becomes
 * depth - its outflow + the inflows its neighbours send it. The sweep here is
 * one pass in the pull form: a band of rows computes the outflows of its
 * rows and one row either side into a per-thread ring of three rows, and
 * every texel gathers its inflows from the ring as soon as the row below it
 * is done. The arithmetic and its order are those of the two-pass scheme
 * that stores nine outflows per texel, so results are bitwise the same at
 * any thread count and with either set of kernels. */
#ifndef SOAK_BAKE_RAIN_FLOW_H
#define SOAK_BAKE_RAIN_FLOW_H

#include "bake_rain_grid.h"
#include "soak/bake.h"
#include "soak/status.h"


/* What a run of sweeps needs besides the depths, made once per grid: who
 * pulls from whom, the second depth buffer, the level + depth maps and the
 * per-thread rows of outflows. The grid's arrays are borrowed, not copied. */
typedef struct soak_rain_flow_plan soak_rain_flow_plan;

/* Which kernels sweep (all give the same bits): AUTO the widest vector ones
 * the CPU runs (AVX-512, AVX2), PORTABLE none, AVX2 at most AVX2 (the last
 * two for the tests). */
typedef enum soak_rain_flow_isa {
    SOAK_RAIN_FLOW_AUTO,
    SOAK_RAIN_FLOW_PORTABLE,
    SOAK_RAIN_FLOW_AVX2
} soak_rain_flow_isa;

/* Prepares sweeps of g for up to soak_bake_threads(exec) threads. */
soak_status soak_rain_flow_create(const soak_rain_flow_grid *g, const soak_bake_exec *exec, soak_rain_flow_isa isa,
                                  soak_rain_flow_plan **out);
void soak_rain_flow_destroy(soak_rain_flow_plan *f);
/* iterations sweeps on depth (w * h, metres); exec must not ask for more
 * threads than f was made for. */
soak_status soak_rain_flow_run(soak_rain_flow_plan *f, double *depth, int iterations, const soak_bake_exec *exec,
                               double progress_lo, double progress_hi);
/* create, run, destroy. */
soak_status soak_rain_flow(const soak_rain_flow_grid *g, double *depth, int iterations, const soak_bake_exec *exec,
                           double progress_lo, double progress_hi);

/* What the steady discharge did with the water, all in m^3/s. */
typedef struct soak_rain_flow_balance {
    double in;      /* sum of the sources */
    double dripped; /* off open edges and down-facing texels */
    double held;    /* into texels with no lower neighbour (pits, flats: puddles) */
    double lost;    /* evaporated on the way */
} soak_rain_flow_balance;

/* Steady flow under constant rain, with the sweeps' routing (same shares,
 * levels of the dry surface: a film much thinner than the level steps):
 * every texel receives source[i] (m^3/s) plus its inflows, loses up to
 * loss * area (m/s of evaporation) and passes the rest on. discharge[i]
 * (m^3/s) is what flows out of texel i; in = dripped + held + lost up to
 * rounding. Texels are taken highest first (ties by index): one pass, the
 * same bits at any thread count. retain is not read. */
soak_status soak_rain_flow_discharge(const soak_rain_flow_grid *g, const double *source, double loss,
                                     double *discharge, soak_rain_flow_balance *balance);

/* The covered texels of g, highest level first, ties by index (the order
 * of soak_rain_flow_discharge); *order is malloc'ed (free it). */
soak_status soak_rain_flow_order(const soak_rain_flow_grid *g, size_t **order, size_t *count);
/* The water on the film's faces moved at the film's speed (soak/bake_rain.h
 * step 3b): one pass down the order in which every fast texel keeps up to
 * retain of what it holds and receives and passes the rest on in the
 * routing's shares, off open edges and down-facing texels; a texel that is
 * not fast, or has no lower neighbour (pits, flats), keeps all it gets, for
 * the sweeps to level. depth in metres; inflow is scratch (w * h);
 * *dripped the volume (m^3) that left. Volume before = volume after +
 * dripped, up to rounding. */
soak_status soak_rain_flow_cascade(const soak_rain_flow_grid *g, const unsigned char *fast, const size_t *order,
                                   size_t count, double *depth, double *inflow, double *dripped);

/* Where what leaves texel i goes, in the routing's shares (those of
 * soak_rain_flow_discharge): share[d] to neighbour d, share[8] off the
 * surface (an open edge; all of it where the texel faces down). Returns 0
 * (all shares 0) where nothing is lower: a pit or flat. */
int soak_rain_flow_shares(const soak_rain_flow_grid *g, size_t i, double share[9]);

/* The width of the stream texel i carries (m): its area over the run of
 * one texel step along the steepest descent (area * max(|a|, |b|) of the
 * descent), sqrt(area) where there is no descent direction. */
double soak_rain_flow_width(const soak_rain_flow_grid *g, size_t i);

#endif
