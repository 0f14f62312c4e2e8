/* Beach waves: the closed form of the model for straight fronts (no
 * turbulence, one reach), saturation below the water line, bounds, rotation
 * of the shoreline, drying in time between wave arrivals, thread
 * independence. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "soak/bake.h"

static void test_closed_form(void)
{
    soak_waves_params p;
    soak_waves_defaults(&p);
    p.front_amplitude = 0;
    p.edge = 0;
    p.reach_min = p.reach_max = 0.3;
    p.shore = -0.2;
    p.direction_deg = 90; /* inland = +v */
    p.time = 13;          /* latest wave j = 1 arrived at 8: ages 5, 13, 21, 29 */
    const double ages[4] = {5, 13, 21, 29};
    double worst = 0;
    for (int k = 0; k <= 60; ++k) {
        double v = -0.5 + k / 60.0, s = v - p.shore, want;
        if (s <= 0) {
            want = 1;
        } else {
            double dry = 1 - exp(-s / p.fringe);
            if (s <= 0.3)
                for (int j = 0; j < 4; ++j) {
                    double fade = j == 3 ? 1 - (13.0 / 8 - 1) : 1; /* oldest fades over the period */
                    dry *= 1 - fade * exp(-ages[j] / p.dry_time) * exp(-s / p.dry_length);
                }
            want = 1 - dry;
        }
        double got;
        check_status("eval", soak_waves_eval(&p, 0.123, v, &got), SOAK_OK);
        worst = fmax(worst, fabs(got - want));
    }
    check_close("straight fronts: wetness = 1 - (1 - fringe) prod(1 - w_j)", worst, 0.0, 1e-12);
}

static void test_map(void)
{
    const int n = 160;
    soak_waves_params p;
    soak_waves_defaults(&p);
    p.seed = 77;
    p.time = 3.3;
    soak_image a, b, c;
    soak_bake_exec one = {1, NULL, NULL}, two = {2, NULL, NULL};
    check_status("bake", soak_bake_waves(&p, n, n, &one, &a), SOAK_OK);
    check_status("bake 2 threads", soak_bake_waves(&p, n, n, &two, &b), SOAK_OK);
    check_true("threads 1 vs 2: identical bytes", memcmp(a.pixels, b.pixels, sizeof(float) * n * n) == 0);
    int bounded = 1, saturated = 1;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            float v = a.pixels[y * n + x];
            bounded &= v >= 0 && v <= 1;
            if ((y + 0.5) / n - 0.5 <= p.shore - 1e-9) saturated &= v == 1.0f;
        }
    check_true("wetness in [0, 1]", bounded);
    check_true("saturated below the still-water line", saturated);
    double top = 0, bottom = 0;
    for (int x = 0; x < n; ++x) top += a.pixels[(n / 2 - 10) * n + x], bottom += a.pixels[(n - 1) * n + x];
    check_true("wetter near the water than far up the beach", top > bottom);
    /* Turning the inland direction from +v to +u turns the map a quarter:
     * value at (u, v) with direction 0 = value at (-v, u) with direction 90. */
    p.direction_deg = 0;
    check_status("bake rotated", soak_bake_waves(&p, n, n, &two, &c), SOAK_OK);
    double worst = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) worst = fmax(worst, fabs(c.pixels[y * n + x] - a.pixels[x * n + (n - 1 - y)]));
    check_close("direction 0 = direction 90 turned a quarter", worst, 0.0, 1e-6);
    soak_image_free(&a), soak_image_free(&b), soak_image_free(&c);
}

static void test_time(void)
{
    soak_waves_params p;
    soak_waves_defaults(&p);
    p.seed = 5;
    int monotone = 1;
    double prev[41];
    for (int k = 0; k < 80; ++k) {
        p.time = 16 + k * 0.1; /* inside one period [16, 24): no arrival */
        for (int i = 0; i <= 40; ++i) {
            double w;
            soak_waves_eval(&p, -0.3 + 0.015 * i, -0.25 + 0.015 * i, &w);
            if (k > 0 && w > prev[i] + 1e-15) monotone = 0;
            prev[i] = w;
        }
    }
    check_true("between arrivals, wetness never increases (drying)", monotone);
    double w;
    p.dry_time = NAN;
    check_status("dry_time NaN", soak_waves_eval(&p, 0, 0, &w), SOAK_ERR_ARG);
    soak_waves_defaults(&p);
    p.reach_max = 0.01; /* < reach_min */
    check_status("reach_max < reach_min", soak_waves_check(&p), SOAK_ERR_ARG);
    soak_waves_defaults(&p);
    soak_image img;
    check_status("width 16385", soak_bake_waves(&p, 16385, 4, NULL, &img), SOAK_ERR_ARG);
}

int main(void)
{
    test_closed_form();
    test_map();
    test_time();
    return check_finish();
}
