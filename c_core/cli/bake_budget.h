/* Budgets of the rain-over-time bakes, estimated from the options before
 * any work (bake_budget.c, issue 51 item 3): drops, ripples and rain. Each returns 0, or the exit
 * code after naming the estimate, its terms, the budget and the variable
 * that raises it (SOAK_MAX_MEMORY_MB, SOAK_MAX_BAKE_S). */
#ifndef SOAK_BAKE_BUDGET_H
#define SOAK_BAKE_BUDGET_H

#include "soak/bake_drops.h"
#include "soak/bake_rain.h"
#include "soak/bake_ripples.h"

/* Estimated single-core seconds a bake may take: SOAK_MAX_BAKE_S, default
 * 10 s + 2 us per output texel (out_texels: width x height x frames). */
double bake_work_budget_s(double out_texels);

/* last_time: the latest frame time (impacts fall until min(duration, it)). */
int bake_drops_budget(const char *cmd, const soak_drops_params *p, long width, long height, long frames,
                      double last_time);
int bake_ripples_budget(const char *cmd, const soak_ripples_params *p, long frames);
/* frames: 0 for the single map (its --steps), else the sequence's count,
 * last_time its latest frame's time. */
int bake_rain_budget(const char *cmd, const soak_rain_params *p, long width, long height, long frames,
                     double last_time);

#endif
