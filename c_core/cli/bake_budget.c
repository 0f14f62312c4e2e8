/* Budgets of the rain-over-time bakes (issue 51 item 3): memory and work of
 * `bake drops` and `bake ripples` estimated from the options before any
 * work and refused over the budget with the numbers and the variable that
 * raises it (SOAK_MAX_MEMORY_MB, SOAK_MAX_BAKE_S).
 *
 * Costs measured on the project machine (release build, one thread,
 * 2026-12-07; c_core/bench has no bench for these yet): drops 0.60-0.64 us
 * and 134 bytes of pending impacts per impact of one 4 s catch-up step
 * (16^2 maps, texel 0.5 and 1 m, 2.9 M and 11.4 M impacts); ripples
 * per ring, per profile sample and per texel a ring covers (six runs at
 * 32^2-256^2, see the constants); rain per texel and time step (5.7e-8 s
 * with no routing, 5.3e-9 s more per --flow-iterations sweep, 256^2 tilted
 * plane, 400 steps) and per exposure ray (5e-8 s on two triangles), and
 * 136-181 bytes per texel (512^2 and 1024^2, frames and single map). The constants are rounded
 * down, so the estimate is a lower bound: a refused bake would have
 * exceeded the budget. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_budget.h"
#include "cli.h"
#include "soak/image.h"

#define DROPS_S_PER_IMPACT 0.5e-6
#define DROPS_BYTES_PER_IMPACT 128.0
#define DROPS_STEP_S (64 * SOAK_DROPS_SLAB) /* CATCH_UP_SLABS of bake_drops_state.c */
#define RAIN_S_PER_TEXEL_STEP 4e-8
#define RAIN_S_PER_TEXEL_SWEEP 4e-9
#define RAIN_S_PER_RAY 2e-8
#define RAIN_BYTES_PER_TEXEL 128.0
#define RIPPLE_S_PER_RING 1e-7     /* measured 2.2e-7 (32^2, tile 20 m: 0.77 M small rings) */
#define RIPPLE_S_PER_SAMPLE 2e-8   /* exp, sin, cos of a profile sample */
#define RIPPLE_S_PER_TEXEL 5e-9    /* measured 1.1-1.5e-8 (64^2 lifetime 5 s, 256^2 rate 50) */
#define RIPPLE_BYTES_PER_RING 48.0 /* struct ring */
#define RIPPLE_BYTES_PER_SAMPLE 16.0
#define RIPPLE_PROFILE_STEP 0.25 /* texels, bake_ripples.c */
#define RIPPLE_ENVELOPE_SIGMAS 3.5
/* Work a bake may take without SOAK_MAX_BAKE_S: 10 s on a small map, more
 * for more output (a 512^2 x 64-frame ripple loop: 43 s). */
#define BAKE_DEFAULT_MAX_S 10.0
#define BAKE_S_PER_OUTPUT_TEXEL 2e-6
#define PI 3.14159265358979323846

double bake_work_budget_s(double out_texels)
{
    const char *e = getenv("SOAK_MAX_BAKE_S");
    if (e && *e) {
        char *end = NULL;
        double v = strtod(e, &end);
        if (*end == '\0' && v > 0 && v <= 1e9) return v;
    }
    return BAKE_DEFAULT_MAX_S + BAKE_S_PER_OUTPUT_TEXEL * out_texels;
}

/* 0, or the exit code after naming the estimate, the budget and its variable. */
static int check(const char *cmd, const char *what, double bytes, double seconds, double out_texels, const char *counts)
{
    char err[1024];
    if (soak_memory_check(what, bytes, 0, err, sizeof err) != SOAK_OK) {
        cli_error(cmd, "%s (%s); refused before any work", err, counts);
        return SOAK_EXIT_USAGE;
    }
    double budget = bake_work_budget_s(out_texels);
    if (seconds <= budget) return 0;
    cli_error(cmd,
              "%s needs at least %.3g s of work on one core (%s); the budget is %.3g s (10 s + 2 us per output "
              "texel; SOAK_MAX_BAKE_S sets it); refused before any work",
              what, seconds, counts, budget);
    return SOAK_EXIT_USAGE;
}

int bake_drops_budget(const char *cmd, const soak_drops_params *p, long width, long height, long frames,
                      double last_time)
{
    double area = (double)width * p->texel_m * (double)height * p->texel_m;
    double flux = soak_drop_flux(p->rate_mm_h, p->min_diameter_mm, SOAK_DROP_D_MAX_MM);
    double rain_s = fmin(p->duration, fmax(0.0, last_time));
    double impacts = flux * area * rain_s, step = flux * area * fmin(rain_s, DROPS_STEP_S);
    double bytes = step * DROPS_BYTES_PER_IMPACT + (double)width * height * 24.0;
    char counts[256];
    snprintf(counts, sizeof counts,
             "%.3g impacts: %.4g per m^2 per s (--rate %g, --min-drop %g) x %.4g m^2 (--width/--height x --texel) x "
             "%g s of rain",
             impacts, flux, p->rate_mm_h, p->min_diameter_mm, area, rain_s);
    return check(cmd, "this drops bake", bytes, impacts * DROPS_S_PER_IMPACT, (double)width * height * frames, counts);
}

int bake_ripples_budget(const char *cmd, const soak_ripples_params *p, long frames)
{
    double texel = p->tile_m / p->size, k = 2 * PI / p->wavelength_m;
    double flux = soak_drop_flux(p->rate_mm_h, p->min_diameter_mm, SOAK_DROP_D_MAX_MM);
    double per_loop = flux * p->tile_m * p->tile_m * p->period;
    double max_age = SOAK_RIPPLES_LIFETIMES * p->lifetime, cg = soak_capillary_group_velocity(k);
    double reach = RIPPLE_ENVELOPE_SIGMAS * p->width_m / texel, live = flux * p->tile_m * p->tile_m * max_age;
    /* Texels a ring covers, averaged over its ages: the annulus r +- reach
     * (the disc r + reach while r < reach), midpoint rule in 64 steps. */
    double texels = 0, samples = 0;
    for (int s = 0; s < 64; ++s) {
        double r = cg * max_age * (s + 0.5) / 64 / texel;
        texels += (r < reach ? PI * (r + reach) * (r + reach) : 4 * PI * r * reach) / 64;
        samples += (fmin(r, reach) + reach) / RIPPLE_PROFILE_STEP / 64;
    }
    double rings_cap = per_loop * (ceil(max_age / p->period) + 1);
    double bytes =
        rings_cap * RIPPLE_BYTES_PER_RING + live * samples * RIPPLE_BYTES_PER_SAMPLE + (double)p->size * p->size * 64.0;
    double seconds =
        (double)frames * live * (RIPPLE_S_PER_RING + samples * RIPPLE_S_PER_SAMPLE + texels * RIPPLE_S_PER_TEXEL);
    char counts[320];
    snprintf(counts, sizeof counts,
             "%.3g rings alive per frame (%.4g impacts per m^2 per s x %g m^2 tile x %g s: 3 --lifetime) covering "
             "%.3g texels each (--ring-width, --wavelength, --tile / --width), %ld frames",
             live, flux, p->tile_m * p->tile_m, max_age, texels, frames);
    return check(cmd, "this ripples bake", bytes, seconds, (double)p->size * p->size * frames, counts);
}

int bake_rain_budget(const char *cmd, const soak_rain_params *p, long width, long height, long frames, double last_time)
{
    double texels = (double)width * height, dt = p->duration / p->steps;
    /* A sequence runs every whole step up to its last frame plus one cut
     * step per frame; the single map runs --steps. */
    double steps = frames > 0 ? floor(fmax(0.0, last_time) / dt) + (double)frames : (double)p->steps;
    double per_step = RAIN_S_PER_TEXEL_STEP + RAIN_S_PER_TEXEL_SWEEP * p->flow_iterations;
    double seconds = texels * (steps * per_step + p->rays * RAIN_S_PER_RAY);
    char counts[320];
    snprintf(counts, sizeof counts,
             "%.3g texels (--width x --height) x (%.4g time steps of %g s (--duration / --steps%s) with %d routing "
             "sweeps each (--flow-iterations) + %d rays (--rays))",
             texels, steps, dt, frames > 0 ? ", up to the last frame's time" : "", p->flow_iterations, p->rays);
    double out_texels = texels * (frames > 0 ? (double)frames : 1.0);
    return check(cmd, "this rain bake", texels * RAIN_BYTES_PER_TEXEL, seconds, out_texels, counts);
}
