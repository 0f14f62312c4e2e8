/* Runnels of the rain bake (soak/bake_rain.h step 3c, bake_rain_runnels.c)
 * on a vertical wall 0.25 m square in rain at 45 deg (E = 1, so the film
 * carries q = r x at x below the top), against references written here:
 *  - the rivulet flux law Q = 4 g theta^3 a^4 / (105 nu) against Simpson's
 *    rule of Nusselt's local flux g h^3 / (3 nu) over the profile h(y) =
 *    theta (a^2 - y^2) / (2 a) (a second method);
 *  - Hartley & Murgatroyd's minimum wetting rate: at a 3 deg contact
 *    angle under 100 mm/h the film breaks above x* = q_min / r and holds
 *    below (x* from their formula evaluated here; the rows 3 texels above
 *    x* have dry gaps, the rows 3 texels below keep Nusselt's film, 1 %);
 *  - at 30 deg under 10 mm/h (everything breaks): the streaks' spacing,
 *    from their centroids along rows, against Troian et al.'s 14 (h l_c^2)^(1/3)
 *    of the film at half height (the median film; 2 %); each streak's
 *    flux from its cross-section A (a = sqrt(3 A / (2 theta))) summed over
 *    the interior streaks of a row per unit width between their centres
 *    against the film's q there (the water balance, 1 %; the two streaks
 *    along the wall's side edges are cut by them and left out);
 *  - contact angle 0 keeps the film; the same seed gives the same bytes, another
 *    seed another pattern; a NaN or 91 deg angle is refused. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "surface_mesh.h"
#include "soak/bake_rain.h"

/* Water at 20 C (CRC Handbook), standard gravity, written out here. */
static const double MU = 1.002e-3, RHO = 998.2, G = 9.80665, SIGMA = 0.0728;
#define NU (MU / RHO)
#define PI 3.14159265358979323846
static const double L = 0.25;
enum { N = 192 };

static void wall(double u, double v, double p[3]) { p[0] = u * L, p[1] = 0.0, p[2] = v * L; }

static double nusselt(double q) { return cbrt(3.0 * NU * q / G); }

static double q_min(double theta) /* Hartley & Murgatroyd 1964, vertical plate */
{
    double gamma = 1.69 * pow(MU * RHO / G, 0.2) * pow(SIGMA * (1.0 - cos(theta)), 0.6);
    return gamma / RHO;
}

static double rivulet_flux(double a, double theta) { return 4.0 * G * pow(theta, 3) * pow(a, 4) / (105.0 * NU); }

static void test_flux_law(void)
{
    const double a = 7e-4, theta = 0.5;
    const int n = 2000;
    double s = 0.0, hstep = 2.0 * a / n;
    for (int k = 0; k <= n; ++k) {
        double y = -a + k * hstep, h = theta * (a * a - y * y) / (2.0 * a),
               w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
        s += w * G * h * h * h / (3.0 * NU);
    }
    s *= hstep / 3.0;
    check_rel("rivulet flux 4 g theta^3 a^4 / (105 nu) = Simpson of Nusselt's flux over the profile",
              rivulet_flux(a, theta), s, 1e-9);
}

static int bake(double rain_mm_h, double angle_deg, uint64_t seed, soak_rain_result *r)
{
    soak_mesh m;
    surface_mesh(&m, 48, 48, wall);
    soak_rain_params p;
    surface_rain_params(&p, soak_v3(0, -1, 1));
    p.rainfall_mm_h = rain_mm_h, p.contact_angle_deg = angle_deg, p.seed = seed;
    char err[256] = "";
    int ok = check_status("bake", soak_bake_rain(&m, N, N, &p, NULL, r, err, sizeof err), SOAK_OK);
    surface_mesh_free(&m);
    return ok;
}

static double below_top(int y) { return L * (y + 0.5) / N; }

static void test_threshold(void)
{
    const double theta = 3.0 * PI / 180.0, r = 100 / 3.6e6, xs = q_min(theta) / r, texel = L / N;
    soak_rain_result res;
    if (!bake(100, 3.0, 1, &res)) return;
    int gaps_above = 1, film_below = 1, rows_above = 0, rows_below = 0;
    double worst = 0.0;
    for (int y = 2; y < N - 2; ++y) {
        double x = below_top(y);
        int dry = 0;
        for (int c = 8; c < N - 8; ++c) {
            double f = res.film.pixels[(size_t)y * N + c];
            dry += f < 1e-6;
            if (x > xs + 3 * texel) worst = fmax(worst, fabs(f / nusselt(r * (y + 1) * texel) - 1.0));
        }
        if (x < xs - 3 * texel) ++rows_above, gaps_above &= dry > 0;
        if (x > xs + 3 * texel) ++rows_below, film_below &= dry == 0;
    }
    printf("threshold: x* = %.4f m (q_min %.3g m^2/s); %d rows above all with gaps, %d below: film within %.3f %%\n",
           xs, q_min(theta), rows_above, rows_below, 100 * worst);
    check_true("threshold: x* inside the wall with rows either side", rows_above > 20 && rows_below > 20);
    check_true("threshold: every row above x* has dry gaps", gaps_above);
    check_true("threshold: every row below x* is covered", film_below);
    check_true("threshold: the film below x* is Nusselt's (1 %)", worst < 0.01);
    soak_rain_result_free(&res);
}

/* The streaks of row y: their centroids (m across) and fluxes (m^3/s). */
static int row_streaks(const soak_rain_result *res, int y, double theta, double *centre, double *flux)
{
    const double texel = L / N;
    int n = 0;
    for (int c = 0; c < N;) {
        if (!(res->film.pixels[(size_t)y * N + c] > 0.0f)) {
            ++c;
            continue;
        }
        double area = 0.0, moment = 0.0;
        for (; c < N && res->film.pixels[(size_t)y * N + c] > 0.0f; ++c) {
            double a = res->film.pixels[(size_t)y * N + c] * texel;
            area += a, moment += a * (c + 0.5) * texel;
        }
        centre[n] = moment / area;
        flux[n++] = rivulet_flux(sqrt(3.0 * area / (2.0 * theta)), theta);
    }
    return n;
}

static void test_spacing_and_balance(void)
{
    const double theta = 30.0 * PI / 180.0, r = 10 / 3.6e6;
    soak_rain_result res;
    if (!bake(10, 30.0, 7, &res)) return;
    double lc2 = SIGMA / (RHO * G), want = 14.0 * cbrt(nusselt(r * L / 2) * lc2);
    double centre[N], flux[N], gap_sum = 0.0, worst = 0.0;
    int gaps = 0, rows = 0;
    for (int y = N / 4; y < N - 2; y += 8) {
        int n = row_streaks(&res, y, theta, centre, flux);
        if (n < 6) continue;
        ++rows;
        double carried = 0.0;
        /* the first and last streaks run along the wall's side edges, cut by them: left out */
        for (int k = 1; k + 2 < n; ++k) gap_sum += centre[k + 1] - centre[k], ++gaps, carried += flux[k];
        /* flux per unit width of the interior streaks against the film's q
         * (what leaves row y: the rain on y + 1 rows of texels) */
        double per_width = carried / (centre[n - 2] - centre[1]), q = r * (y + 1) * L / N;
        worst = fmax(worst, fabs(per_width / q - 1.0));
    }
    double got = gaps ? gap_sum / gaps : 0.0;
    printf("runnels at 30 deg: spacing %.2f mm (reported %.2f) vs Troian et al. %.2f mm; %d texels broke; "
           "worst row balance %.3f %% over %d rows\n",
           1e3 * got, 1e3 * res.runnel_spacing, 1e3 * want, res.runnel_texels, 100 * worst, rows);
    check_true("runnels: streaks found in >= 10 rows", rows >= 10);
    check_rel("runnels: mean spacing of the streaks vs 14 (h l_c^2)^1/3 at half height (2 %)", got, want, 0.02);
    check_true("runnels: streak fluxes per unit width = the film's q in every row (1 %)", worst < 0.01);
    soak_rain_result same, other, none;
    if (bake(10, 30.0, 7, &same)) {
        check_true("runnels: the same seed, the same bytes",
                   !memcmp(same.film.pixels, res.film.pixels, sizeof(float) * N * N));
        soak_rain_result_free(&same);
    }
    if (bake(10, 30.0, 8, &other)) {
        check_true("runnels: another seed, another pattern",
                   memcmp(other.film.pixels, res.film.pixels, sizeof(float) * N * N) != 0);
        soak_rain_result_free(&other);
    }
    if (bake(10, 0.0, 7, &none)) {
        double worst_film = 0.0;
        for (int y = 2; y < N; ++y)
            for (int c = 0; c < N; ++c)
                worst_film =
                    fmax(worst_film, fabs(none.film.pixels[(size_t)y * N + c] / nusselt(r * (y + 1) * L / N) - 1.0));
        printf("contact angle 0: worst film vs Nusselt %.3g\n", worst_film);
        check_true("contact angle 0: the film holds (Nusselt within 1e-5 everywhere)", worst_film < 1e-5);
        soak_rain_result_free(&none);
    }
    soak_rain_result_free(&res);
}

static void test_refusals(void)
{
    soak_rain_params p;
    soak_rain_defaults(&p);
    p.contact_angle_deg = NAN;
    check_status("NaN contact angle refused", soak_rain_check(&p), SOAK_ERR_ARG);
    p.contact_angle_deg = 91;
    check_status("91 deg contact angle refused", soak_rain_check(&p), SOAK_ERR_ARG);
}

int main(void)
{
    test_flux_law();
    test_threshold();
    test_spacing_and_balance();
    test_refusals();
    return check_finish();
}
