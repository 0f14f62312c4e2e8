/* The stability sweep's shared vocabulary (test_stability.c): one tally per
 * function, the adversarial argument pickers and the output predicates. The
 * sweeps draw from one random stream in a fixed order, so they live in several
 * files but run from one driver. */
#ifndef SOAK_TEST_STABILITY_ARGS_H
#define SOAK_TEST_STABILITY_ARGS_H

#include "soak/rng.h"
#include "soak/status.h"
#include "soak/vec.h"

typedef struct {
    const char *name;
    long calls, ok, bad_out, acc_invalid, rej_valid;
} tally;

#define MAX_TALLY 96
typedef struct {
    tally t[MAX_TALLY];
    int n;
    long total;
} tallies;

/* valid: every argument inside its documented range; out_ok: the outputs
 * (looked at only on SOAK_OK) are finite and in range. */
void rec(tallies *ts, const char *name, int valid, soak_status st, int out_ok);

/* The call runs before its outputs are looked at. */
#define REC(name, valid, call, check)                                                                                  \
    do {                                                                                                               \
        soak_status st_ = (call);                                                                                      \
        rec(ts, name, valid, st_, st_ == SOAK_OK && (check));                                                          \
    } while (0)

static inline int fin(double x) { return x == x && x - x == 0.0; }
static inline int in01(double x) { return fin(x) && x >= 0.0 && x <= 1.0; }
static inline int nonneg(double x) { return fin(x) && x >= 0.0; }
static inline int rng_ok(double x, double lo, double hi) { return x >= lo && x <= hi; }

double uni(soak_rng *r);
double pick_valid(soak_rng *r, double lo, double hi);
double pick_invalid(soak_rng *r, double lo, double hi);
double arg(soak_rng *r, double lo, double hi, double pbad, int *valid);
double call_pbad(soak_rng *r);
soak_vec3 pick_dir(soak_rng *r, double pbad, int *unit, int *upper);
int unit_out(soak_vec3 v);

/* stability_optics.c */
void sweep_fresnel(tallies *ts, soak_rng *r, int n);
void monotone_fresnel(void);
void sweep_ggx(tallies *ts, soak_rng *r, int n, long *overflow_ok);
void sweep_phase(tallies *ts, soak_rng *r, int n);
void sweep_film(tallies *ts, soak_rng *r, int n);
void monotone_film(void);

/* stability_layers.c (the Weidlich-Wilkie and soak_models() sweeps too) */
void sweep_porous(tallies *ts, soak_rng *r, int n);
void sweep_porous_ggx(tallies *ts, soak_rng *r, int setups, int evals, long *overflow_ok);
void monotone_porous(soak_rng *r);
void sweep_ww(tallies *ts, soak_rng *r, int n, long *overflow_ok);
void sweep_models(tallies *ts, soak_rng *r, int evals_per_model, long *overflow_ok);

#endif
