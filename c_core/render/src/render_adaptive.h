/* Render to an error: a tile stops taking samples once every pixel's mean
 * luminance is known to a relative standard error below the target. */
#ifndef SOAK_RENDER_ADAPTIVE_H
#define SOAK_RENDER_ADAPTIVE_H

/* Samples a pixel needs before its variance estimate is trusted: fewer miss
 * rare paths (a caustic, a glint) and stop on a black, falsely certain pixel. */
#define RT_ADAPTIVE_MIN_SPP 16
/* Luminance below which the error is taken as absolute (target x this): dark
 * pixels would otherwise never converge, and their noise does not show. */
#define RT_ADAPTIVE_FLOOR 0.01

/* 1 when each of the n pixels (sum and sum of squares of its samples'
 * luminance, count of samples) has at least RT_ADAPTIVE_MIN_SPP samples and a
 * standard error of its mean below target * max(mean, RT_ADAPTIVE_FLOOR). */
int rt_adaptive_converged(const double *sum_y, const double *sum_y2, const int *count, int n, double target);

#endif
