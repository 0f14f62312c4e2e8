/* Splashes of the drops bake (soak/bake_drops.h, bake_drops_splash.c)
 * against references written out here:
 *  - K = We Oh^-0.4 from water's properties and Atlas et al.'s fall speed,
 *    and Cossali et al.'s (1997) threshold 2100 + 5880 (h/D)^1.44;
 *  - the threshold: the drop diameter D* where K(D*) = K_c is found here by
 *    bisection, for films of 0.05, 0.2 and 1 mm; a drop 1 % below D* never
 *    splashes, 1 % above always does; a dry texel never splashes;
 *  - the secondaries: Marmanis & Thoroddsen's finger count computed here,
 *    their volumes summing to the thrown share of the drop's, each landing
 *    at the ballistic range of a 45 deg launch within [(s v / 2)^2, (s v)^2]
 *    / g of the impact;
 *  - the bake: water on the map = the sum of the drop volumes (1e-5) with
 *    splashes on (some impacts do splash), a thrown share of 0 gives the
 *    bytes of the bake without splashes, 1 and 2 threads the same bytes,
 *    and splashing wets texels no primary splat reaches (spots). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "soak/bake_drops.h"

#define PI 3.14159265358979323846
/* Water at 20 C (CRC Handbook), standard gravity, written out here. */
static const double RHO = 998.2, SIGMA = 0.0728, MU = 1.002e-3, G = 9.80665;

static double fall_speed(double d_mm) /* Atlas et al. 1973 */
{
    double v = 9.65 - 10.3 * exp(-0.6 * d_mm);
    return v > 0 ? v : 0;
}

static double k_of(double d_mm)
{
    double d = d_mm * 1e-3, v = fall_speed(d_mm), we = RHO * v * v * d / SIGMA, oh = MU / sqrt(RHO * SIGMA * d);
    return we * pow(oh, -0.4);
}

static double k_crit(double film_m, double d_mm)
{
    double delta = fmin(1.0, film_m / (d_mm * 1e-3));
    return 2100 + 5880 * pow(delta, 1.44);
}

/* D* (mm) with K(D*) = K_c(film, D*), by bisection on [0.2, 6] mm. */
static double threshold_diameter(double film_m)
{
    double a = 0.2, b = 6.0;
    for (int k = 0; k < 200; ++k) {
        double m = 0.5 * (a + b);
        if (k_of(m) > k_crit(film_m, m)) b = m;
        else a = m;
    }
    return 0.5 * (a + b);
}

static soak_drops_params splash_params(void)
{
    soak_drops_params p;
    soak_drops_defaults(&p);
    p.splash = 1;
    p.seed = 11;
    return p;
}

static void test_formulas(void)
{
    const double d[] = {0.5, 1.0, 2.0, 4.0};
    for (int k = 0; k < 4; ++k) {
        char what[160];
        snprintf(what, sizeof what, "K = We Oh^-0.4 at D = %g mm", d[k]);
        check_rel(what, soak_splash_k(d[k], fall_speed(d[k])), k_of(d[k]), 1e-12);
        snprintf(what, sizeof what, "Cossali K_c under D = %g mm on a 0.3 mm film", d[k]);
        check_rel(what, soak_splash_k_critical(3e-4, d[k]), k_crit(3e-4, d[k]), 1e-12);
        double v = fall_speed(d[k]), dm = d[k] * 1e-3;
        double n = sqrt(RHO * v * v * dm / SIGMA) * pow(RHO * v * dm / MU, 0.25) / (4 * sqrt(3.0));
        snprintf(what, sizeof what, "fingers at D = %g mm: round(We^1/2 Re^1/4 / 4 sqrt 3) = %.0f", d[k],
                 floor(n + 0.5));
        check_true(what, soak_splash_fingers(d[k], v) == (int)fmax(1, floor(n + 0.5)));
    }
    check_close("K of a NaN drop is 0", soak_splash_k(NAN, 5), 0, 0);
    check_close("K_c of a NaN film is the film-free 2100", soak_splash_k_critical(NAN, 2), 2100, 0);
    check_true("fingers of a NaN speed: 1", soak_splash_fingers(2, NAN) == 1);
}

static void test_threshold(void)
{
    soak_drops_params p = splash_params();
    soak_splash_drop out[SOAK_SPLASH_MAX_FINGERS];
    const double films[] = {5e-5, 2e-4, 1e-3};
    for (int f = 0; f < 3; ++f) {
        double ds = threshold_diameter(films[f]);
        printf("splash threshold on a %.2f mm film: D* = %.3f mm (K %.0f)\n", films[f] * 1e3, ds, k_of(ds));
        int below = 0, above = 0;
        for (uint32_t i = 0; i < 50; ++i) {
            soak_drop_impact lo = {100, 100, 0.01 * i, ds * 0.99, 0, i}, hi = lo;
            hi.d_mm = ds * 1.01;
            below += soak_splash_throw(&p, &lo, films[f], out) > 0;
            above += soak_splash_throw(&p, &hi, films[f], out) > 0;
        }
        char what[160];
        snprintf(what, sizeof what, "film %.2f mm: no splash 1 %% below D* = %.3f mm (%d of 50)", films[f] * 1e3, ds,
                 below);
        check_true(what, below == 0);
        snprintf(what, sizeof what, "film %.2f mm: splash 1 %% above D* (%d of 50)", films[f] * 1e3, above);
        check_true(what, above == 50);
    }
    soak_drop_impact big = {100, 100, 0.5, 5.0, 3, 4};
    check_true("a dry texel never splashes", soak_splash_throw(&p, &big, 0.0, out) == 0);
    p.splash = 0;
    check_true("splashes off: no splash", soak_splash_throw(&p, &big, 1e-4, out) == 0);
}

static void test_secondaries(void)
{
    soak_drops_params p = splash_params();
    p.texel_m = 1e-3;
    soak_splash_drop out[SOAK_SPLASH_MAX_FINGERS];
    soak_drop_impact imp = {200, 300, 1.3, 2.5, 7, 9};
    int n = soak_splash_throw(&p, &imp, 1e-4, out);
    double v = fall_speed(2.5), vol = 0, d = 2.5e-3;
    int fingers = (int)floor(sqrt(RHO * v * v * d / SIGMA) * pow(RHO * v * d / MU, 0.25) / (4 * sqrt(3.0)) + 0.5);
    printf("2.5 mm drop on a 0.1 mm film: %d secondaries of %.3f mm\n", n, n ? out[0].d_mm : 0);
    check_true("secondaries = Marmanis-Thoroddsen finger count", n == fingers);
    double r_lo = pow(p.splash_speed * v / 2, 2) / G / p.texel_m, r_hi = pow(p.splash_speed * v, 2) / G / p.texel_m;
    int in_range = 1;
    for (int k = 0; k < n; ++k) {
        vol += PI / 6 * pow(out[k].d_mm, 3);
        double r = hypot(out[k].x - imp.x, out[k].y - imp.y);
        in_range &= r >= r_lo * (1 - 1e-9) && r <= r_hi * (1 + 1e-9);
        in_range &= fabs(r - out[k].v * out[k].v / G / p.texel_m) <= 1e-9 * r;
    }
    check_rel("secondary volumes = thrown share of the drop", vol, p.splash_fraction * PI / 6 * pow(2.5, 3), 1e-12);
    check_true("every secondary at the 45 deg ballistic range u^2 / g, u in [s v / 2, s v]", in_range);
}

static double map_water(const soak_image *img, double capacity, double texel)
{
    double w = 0;
    for (size_t i = 0; i < (size_t)img->width * img->height; ++i) w += img->pixels[i] * capacity * texel * texel;
    return w;
}

static soak_image bake(const soak_drops_params *p, int size, double t, int threads, size_t *splashed)
{
    soak_drops_state *st = NULL;
    soak_image img = {0, 0, 0, NULL};
    soak_bake_exec ex = {threads, NULL, NULL};
    check_status("create", soak_drops_create(p, NULL, size, size, &st), SOAK_OK);
    check_status("frame", soak_drops_frame(st, t, &ex, &img), SOAK_OK);
    if (splashed) *splashed = soak_drops_splashed(st);
    soak_drops_destroy(st);
    return img;
}

static void test_bake(void)
{
    const int size = 128;
    const long slabs = 32;
    soak_drops_params p = splash_params();
    p.rate_mm_h = 30, p.capacity_m = 1; /* never full: all water stays */
    size_t splashed = 0, n = 0;
    soak_image a = bake(&p, size, slabs * SOAK_DROPS_SLAB, 1, &splashed);
    soak_drop_impact *v = NULL;
    check_status("impacts", soak_drops_impacts(&p, NULL, size, size, 0, slabs, &v, &n), SOAK_OK);
    double want = 0;
    for (size_t i = 0; i < n; ++i) want += PI / 6 * pow(v[i].d_mm * 1e-3, 3);
    printf("bake: %zu of %zu impacts splashed\n", splashed, n);
    check_true("bake: some impacts splash (>= 5 %)", splashed * 20 >= n && n > 100);
    check_rel("bake with splashes: water on the map = sum of drop volumes", map_water(&a, 1, p.texel_m), want, 1e-5);
    soak_image b = bake(&p, size, slabs * SOAK_DROPS_SLAB, 2, NULL);
    check_true("bake with splashes: 1 and 2 threads the same bytes",
               !memcmp(a.pixels, b.pixels, sizeof(float) * size * size));
    soak_image_free(&b);
    /* texels wet without splashes vs with: the secondaries' spots */
    p.splash = 0;
    soak_image plain = bake(&p, size, slabs * SOAK_DROPS_SLAB, 2, NULL);
    int spots = 0;
    for (int i = 0; i < size * size; ++i) spots += plain.pixels[i] == 0 && a.pixels[i] > 0;
    printf("bake: %d texels dry without splashes are wet with them\n", spots);
    check_true("splashes wet texels no splat reaches", spots > 0);
    p.splash = 1, p.splash_fraction = 0;
    soak_image none = bake(&p, size, slabs * SOAK_DROPS_SLAB, 1, NULL);
    check_true("thrown share 0: the bytes of the bake without splashes",
               !memcmp(none.pixels, plain.pixels, sizeof(float) * size * size));
    p.splash_fraction = NAN;
    check_status("NaN splash fraction refused", soak_drops_check(&p), SOAK_ERR_ARG);
    p.splash_fraction = 0.2, p.splash_speed = 1.5;
    check_status("splash speed above 1 refused", soak_drops_check(&p), SOAK_ERR_ARG);
    soak_image_free(&a), soak_image_free(&plain), soak_image_free(&none);
    free(v);
}

int main(void)
{
    test_formulas();
    test_threshold();
    test_secondaries();
    test_bake();
    return check_finish();
}
