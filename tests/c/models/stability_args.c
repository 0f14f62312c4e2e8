/* Adversarial arguments and tallies for the stability sweep (see
 * stability_args.h and test_stability.c). */
#include "stability_args.h"

#include <math.h>
#include <string.h>

static tally *tl(tallies *ts, const char *name)
{
    for (int i = 0; i < ts->n; ++i)
        if (!strcmp(ts->t[i].name, name)) return &ts->t[i];
    tally *t = &ts->t[ts->n++];
    memset(t, 0, sizeof *t);
    t->name = name;
    return t;
}

void rec(tallies *ts, const char *name, int valid, soak_status st, int out_ok)
{
    tally *t = tl(ts, name);
    ++t->calls;
    ++ts->total;
    if (st == SOAK_OK) {
        ++t->ok;
        if (!valid) ++t->acc_invalid;
        if (!out_ok) ++t->bad_out;
    } else if (valid) {
        ++t->rej_valid;
    }
}

/* ---- adversarial values ----------------------------------------------- */

double uni(soak_rng *r) { return soak_rng_uniform(r); }

static const double specials[] = {0.0,  -0.0, 5e-324,      1e-310, 1e-300,        1e-160, 1e-17, 1e-9,
                                  1e-3, 0.5,  1.0 - 1e-16, 1.0,    1.0 + 2.2e-16, 2.0,    1e3,   1e300};

/* A value inside [lo, hi]: the ends, one ulp inside them, the specials that
 * fall inside, log-spaced points crowding each end, or uniform. */
double pick_valid(soak_rng *r, double lo, double hi)
{
    double u = uni(r), w = hi - lo;
    if (u < 0.25) return lo + w * uni(r);
    if (u < 0.33) return lo;
    if (u < 0.41) return hi;
    if (u < 0.45) return nextafter(lo, hi);
    if (u < 0.49) return nextafter(hi, lo);
    if (u < 0.72) {
        for (int tries = 0; tries < 4; ++tries) {
            double s = specials[(int)(uni(r) * (sizeof specials / sizeof specials[0]))];
            if (s >= lo && s <= hi) return s;
            if (-s >= lo && -s <= hi) return -s;
        }
        return lo + w * uni(r);
    }
    double t = pow(10.0, -320.0 * uni(r));
    double v = u < 0.86 ? lo + w * t : hi - w * t;
    return v < lo ? lo : (v > hi ? hi : v);
}

double pick_invalid(soak_rng *r, double lo, double hi)
{
    double u = uni(r);
    if (u < 0.25) return NAN;
    if (u < 0.35) return INFINITY;
    if (u < 0.45) return -INFINITY;
    if (u < 0.55) return nextafter(lo, -INFINITY);
    if (u < 0.65) return nextafter(hi, INFINITY);
    if (u < 0.75) return lo - 1.0 - fabs(lo);
    if (u < 0.85) return hi + 1.0 + fabs(hi);
    return u < 0.93 ? 1e300 : -1e300;
}

/* One argument: invalid with probability pbad. *valid is and-ed with the
 * documented range test of the value drawn. */
double arg(soak_rng *r, double lo, double hi, double pbad, int *valid)
{
    double x = uni(r) < pbad ? pick_invalid(r, lo, hi) : pick_valid(r, lo, hi);
    if (!(x >= lo && x <= hi)) *valid = 0;
    return x;
}

/* Probability that an argument of this call is invalid: a third of the
 * calls exercise rejection, the rest the valid range. */
double call_pbad(soak_rng *r) { return uni(r) < 0.33 ? 0.3 : 0.0; }

static const double cos_specials[] = {0.0, 5e-324, 1e-310, 1e-300, 1e-160, 1e-17, 1e-9, 1e-4, 0.5, 1.0 - 1e-16, 1.0};

/* A direction; *unit: unit within the documented 1e-5 on |v|^2 (finite),
 * *upper: additionally z > 0. Grazing and denormal z are frequent; a
 * quarter of the valid ones are below the horizon. */
soak_vec3 pick_dir(soak_rng *r, double pbad, int *unit, int *upper)
{
    double u = uni(r);
    soak_vec3 v;
    if (u < pbad) {
        double k = uni(r);
        if (k < 0.2) v = soak_v3(NAN, 0.0, 1.0);
        else if (k < 0.4) v = soak_v3(0.0, INFINITY, 0.5);
        else if (k < 0.5) v = soak_v3(0.0, 0.0, 0.0);
        else if (k < 0.7) v = soak_v3(0.0, 0.6, 0.8 * 1.0001); /* |v|^2 off by 1.3e-4 */
        else if (k < 0.8) v = soak_v3(3.0, 0.0, 0.0);
        else v = soak_v3(0.0, 0.0, sqrt(1.0 + 2e-5));
    } else {
        double z = uni(r) < 0.5 ? cos_specials[(int)(uni(r) * (sizeof cos_specials / sizeof cos_specials[0]))] : uni(r);
        if (uni(r) < 0.25) z = -z;
        double s = sqrt(fmax(0.0, 1.0 - z * z)), phi = uni(r) < 0.2 ? 0.0 : 2.0 * SOAK_PI * uni(r);
        v = soak_v3(s * cos(phi), s * sin(phi), z);
        if (uni(r) < 0.05) v = soak_v3_scale(v, sqrt(1.0 + (uni(r) < 0.5 ? 4e-6 : -4e-6))); /* inside the tolerance */
    }
    double l2 = v.x * v.x + v.y * v.y + v.z * v.z;
    *unit = fin(l2) && fabs(l2 - 1.0) <= 1e-5;
    *upper = *unit && v.z > 0.0;
    return v;
}

int unit_out(soak_vec3 v) { return fin(v.x) && fin(v.y) && fin(v.z) && fabs(soak_v3_dot(v, v) - 1.0) < 1e-6; }
