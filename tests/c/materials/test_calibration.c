/* Presets against published measurements (docs/calibration.md):
 *  - every preset with a "measured" group reproduces its measured wet/dry
 *    ratio within the measurement's spread, the chain evaluated at the
 *    sample's (grey) dry albedo, and sand has one (no vacuous pass);
 *  - presets without one follow the stated rule (sand's transport ratio);
 *  - copper's n, k are the measured table interpolated at 650/550/450 nm, and
 *    its normal reflectance is copper's measured colour; aluminium likewise;
 *  - water's absorption is the band average of Pope & Fry 1997.
 * The references are tables of published measurements typed in here, not
 * numbers produced by the code under test. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "testutil.h"
#include "soak/fresnel.h"
#include "soak/preset.h"
#include "soak/vdhulst.h"
#include "soak/wetness.h"

static double f0(double n, double k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); }

static void check_measured(const soak_preset_db *db, const soak_liquid *water)
{
    int count = 0;
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        if (!p->has_measured) continue;
        ++count;
        double r = -1.0;
        char what[200];
        snprintf(what, sizeof what, "%s: chain at the sample's dry albedo %.3f", p->name, p->measured_dry_albedo);
        if (!check_status(what, soak_wetness_measured_ratio(p, water, p->measured_wetness, &r), SOAK_OK)) continue;
        snprintf(what, sizeof what, "%s: the measurement states its light (sun zenith %.0f deg)", p->name,
                 p->measured_sun_zenith_deg);
        check_true(what, soak_in_range(p->measured_sun_zenith_deg, 0.0, 90.0));
        snprintf(what, sizeof what, "%s: model wet/dry %.3f vs measured %.3f +- %.3f", p->name, r, p->measured_ratio,
                 p->measured_spread);
        check_close(what, r, p->measured_ratio, p->measured_spread);
    }
    const soak_preset *sand = soak_presets_find(db, "sand");
    check_true("sand carries a measurement", sand && sand->has_measured);
    check_true("at least one calibrated preset", count >= 1);
    if (sand && sand->has_measured) {
        /* The measurement itself (field albedos 0.40 -> 0.25 and 0.39 -> 0.23). */
        check_close("sand measured ratio = centre of 0.25/0.40 and 0.23/0.39", sand->measured_ratio,
                    0.5 * (0.25 / 0.40 + 0.23 / 0.39), 5e-4);
        check_true("sand measured spread covers both ratios",
                   fabs(0.25 / 0.40 - sand->measured_ratio) <= sand->measured_spread &&
                       fabs(0.23 / 0.39 - sand->measured_ratio) <= sand->measured_spread);
        /* Before the fix the chain gave 0.50 here; the old stacked model must be outside. */
        double r = 0.0;
        soak_preset old = *sand;
        old.phase_wet.g1 = 0.7; /* [JLD99]'s eyeballed value */
        check_true("[JLD99]'s wet g misses the measurement",
                   soak_wetness_measured_ratio(&old, water, sand->measured_wetness, &r) == SOAK_OK &&
                       fabs(r - sand->measured_ratio) > sand->measured_spread);
        /* Clapp & Hornberger 1978, Table 2: sand porosity 0.395. */
        check_close("sand porosity = Clapp & Hornberger's sand", sand->porosity, 0.395, 0.0);
        check_close("the field albedo is at saturation: wetness = porosity", sand->measured_wetness, sand->porosity,
                    0.0);
    }
}


/* Directional-hemispherical albedo under a sun (soak_wetness_albedo_sun):
 *  - identity: its cosine-weighted hemispherical mean is the bihemispherical
 *    albedo soak_wetness_eval gives for uniform diffuse light;
 *  - identity: total - diffuse part = interface area x Fresnel(theta) of the
 *    liquid (the mirror reflection the sun sees; film.h's T(0));
 *  - dry: a Lambertian body, the same under every light. */
static void check_sun(const soak_preset_db *db, const soak_liquid *water)
{
    const char *names[] = {"sand", "asphalt", "paper", "copper"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
        const soak_preset *p = soak_presets_find(db, names[k]);
        if (!check_true("preset present", p != NULL)) continue;
        const double wets[] = {0.0, 0.5 * p->porosity, 1.0};
        for (int j = 0; j < 3; ++j) {
            soak_wet_input in = soak_wet_input_steady(p, wets[j]);
            soak_wet_params w;
            if (!check_status("eval", soak_wetness_eval(p, water, &in, &w), SOAK_OK)) continue;
            /* Gauss-Legendre would be better; the midpoint rule in mu with
             * 400 nodes is exact to ~1e-6 here and independent of film.c. */
            const int n = 400;
            soak_rgb mean = {0, 0, 0};
            double worst_mirror = 0.0;
            int ok = 1;
            for (int i = 0; i < n; ++i) {
                double mu = (i + 0.5) / n;
                soak_rgb a, t;
                if (soak_wetness_albedo_sun(p, water, &w, mu, &a, &t) != SOAK_OK) {
                    ok = 0;
                    break;
                }
                mean = soak_rgb3(mean.r + 2.0 * mu * t.r / n, mean.g + 2.0 * mu * t.g / n, mean.b + 2.0 * mu * t.b / n);
                double F = 0.0;
                soak_fresnel_dielectric(mu, water->ior, &F, NULL);
                if (p->kind != SOAK_KIND_CONDUCTOR)
                    worst_mirror = fmax(worst_mirror, fabs((t.g - a.g) - soak_wet_interface_area(&w) * F));
            }
            char what[160];
            snprintf(what, sizeof what, "%s w=%.3f: every sun angle evaluates", p->name, wets[j]);
            if (!check_true(what, ok)) continue;
            snprintf(what, sizeof what, "%s w=%.3f: hemispherical mean of the sun albedo = diffuse-light albedo (G)",
                     p->name, wets[j]);
            check_close(what, mean.g, w.albedo_total.g, p->kind == SOAK_KIND_CONDUCTOR ? 1e-12 : 2e-5);
            if (p->kind != SOAK_KIND_CONDUCTOR) {
                snprintf(what, sizeof what, "%s w=%.3f: mirror part = interface area x Fresnel", p->name, wets[j]);
                check_close(what, worst_mirror, 0.0, 1e-12);
            }
            if (wets[j] == 0.0 && p->kind != SOAK_KIND_CONDUCTOR) {
                soak_rgb a, t;
                soak_wetness_albedo_sun(p, water, &w, 0.3, &a, &t);
                check_true("dry: the sun albedo is the dry albedo", a.r == p->albedo.r && t.b == p->albedo.b);
            }
        }
    }
    /* Asphalt: under diffuse light the wet total is about twice the dry one
     * (the water's hemispherical reflectance 0.066 over a 0.04 body); under a
     * sun at 30 deg the water adds F(30 deg) = 0.0205 only. */
    const soak_preset *a = soak_presets_find(db, "asphalt");
    if (a) {
        soak_wet_input in = soak_wet_input_steady(a, 1.0);
        soak_wet_params w;
        soak_rgb d, t;
        if (soak_wetness_eval(a, water, &in, &w) == SOAK_OK &&
            check_status("asphalt sun", soak_wetness_albedo_sun(a, water, &w, cos(SOAK_PI / 6), &d, &t), SOAK_OK)) {
            double F = 0.0;
            soak_fresnel_dielectric(cos(SOAK_PI / 6), water->ior, &F, NULL);
            check_close("asphalt wet, sun at 30 deg: total - diffuse = Fresnel(30 deg)", t.g - d.g, F, 1e-12);
            check_true("asphalt wet: sun total well below the diffuse-light total", t.g < 0.7 * w.albedo_total.g);
        }
    }
    soak_rgb x, y;
    soak_wet_params w0;
    memset(&w0, 0, sizeof w0);
    const soak_preset *sand = soak_presets_find(db, "sand");
    check_status("cos_i > 1 rejected", soak_wetness_albedo_sun(sand, water, &w0, 1.5, &x, &y), SOAK_ERR_ARG);
    check_status("cos_i NaN rejected", soak_wetness_albedo_sun(sand, water, &w0, NAN, &x, &y), SOAK_ERR_ARG);
    check_status("NULL rejected", soak_wetness_albedo_sun(sand, water, NULL, 0.5, &x, &y), SOAK_ERR_NULL);
}


/* Riese & Keller 2018 (c_core/data/measured/riese2018_rgb.csv, reduced by
 * scripts/calibration_reduce.py): one soil drying outdoors, nadir camera,
 * sun at the logged times. The 2 cm probe lags the surface, so moisture /
 * porosity is not the surface's fill (docs/calibration.md); what the data
 * do fix is the end points: a wet plateau (probe >= 32 %) against the
 * driest bin. Model: the granular rule (sand's phases) with the soil's
 * porosity (Clapp & Hornberger 1978, silt loam 0.485), re-based on the
 * driest bin's green reflectance, saturated, under the plateau's mean sun,
 * without the mirror part (a nadir camera does not see it). Spread: the
 * plateau bins' standard deviation and the driest bin's, root-sum-square. */
#define RIESE_MAX_ROWS 64
static int read_riese(double (*rows)[11])
{
    char path[1024];
    const char *me = __FILE__, *cut = strstr(me, "tests/c/materials/test_calibration.c");
    if (!cut) return 0;
    snprintf(path, sizeof path, "%.*sc_core/data/measured/riese2018_rgb.csv", (int)(cut - me), me);
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    char line[512];
    int n = 0;
    if (!fgets(line, sizeof line, f)) n = -1; /* header */
    while (n >= 0 && n < RIESE_MAX_ROWS && fgets(line, sizeof line, f)) {
        double *r = rows[n];
        if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", r, r + 1, r + 2, r + 3, r + 4, r + 5, r + 6,
                   r + 7, r + 8, r + 9, r + 10) == 11)
            ++n;
    }
    fclose(f);
    return n;
}

static void check_riese(const soak_preset_db *db, const soak_liquid *water)
{
    double rows[RIESE_MAX_ROWS][11];
    int n = read_riese(rows);
    if (!check_true("Riese & Keller 2018 reduced table read (>= 10 bins)", n >= 10)) return;
    const double g0 = rows[0][5], g0_sd = rows[0][8];
    double sum = 0, sum2 = 0, zen = 0;
    int m = 0;
    for (int i = 0; i < n; ++i) {
        if (rows[i][0] < 32.0) continue;
        double r = rows[i][5] / g0;
        sum += r;
        sum2 += r * r;
        zen += rows[i][10];
        ++m;
    }
    if (!check_true("wet plateau has >= 5 bins", m >= 5)) return;
    const double measured = sum / m, sd = sqrt((sum2 - m * measured * measured) / (m - 1));
    const double spread = sqrt(sd * sd + (measured * g0_sd / g0) * (measured * g0_sd / g0));
    zen /= m;
    const soak_preset *sand = soak_presets_find(db, "sand");
    if (!check_true("sand preset present", sand != NULL)) return;
    soak_preset soil = *sand;
    soil.porosity = 0.485; /* Clapp & Hornberger 1978, Table 2, silt loam */
    soil.albedo = soak_rgb3(g0, g0, g0);
    soak_wet_params w;
    soak_rgb d, t;
    soak_wet_input in = soak_wet_input_steady(&soil, soil.porosity);
    if (!check_status("soil derive", soak_preset_derive(&soil), SOAK_OK) ||
        !check_status("soil eval", soak_wetness_eval(&soil, water, &in, &w), SOAK_OK) ||
        !check_status("soil sun", soak_wetness_albedo_sun(&soil, water, &w, cos(zen * SOAK_PI / 180), &d, &t), SOAK_OK))
        return;
    char what[200];
    snprintf(what, sizeof what, "soil (Riese & Keller 2018): saturated/driest %.3f vs measured %.3f +- %.3f (sun %.0f deg)",
             d.g / g0, measured, spread, zen);
    check_close(what, d.g / g0, measured, spread);
}


/* van de Hulst's approximation (soak/vdhulst.h) against the exact
 * semi-infinite albedo for isotropic scattering, r = 1 - 2 sqrt(1 - omega)
 * int_0^1 H(mu) mu dmu with Chandrasekhar's H function (Radiative Transfer,
 * 1950, ch. V: H(mu) = 1 / (1 - (omega/2) mu int_0^1 H(mu')/(mu + mu') dmu'),
 * solved by iteration on Gauss-Legendre nodes). The chain inverts the same
 * formula at the dry albedo, so dry is exact and only the wet/dry ratio
 * carries its error: the budget stated in docs/calibration.md and asserted
 * here is 1.4 % on the ratio for dry albedos >= 0.02 and ratios >= 0.3
 * (the calibrated wet g absorbs the systematic part). */
#define GL_N 48

static double exact_isotropic_albedo(double omega, const double *x, const double *w)
{
    double h[GL_N], hn[GL_N];
    for (int i = 0; i < GL_N; ++i) h[i] = 1.0;
    for (int it = 0; it < 20000; ++it) {
        double change = 0.0;
        for (int i = 0; i < GL_N; ++i) {
            double s = 0.0;
            for (int j = 0; j < GL_N; ++j) s += w[j] * h[j] / (x[i] + x[j]);
            hn[i] = 1.0 / (1.0 - 0.5 * omega * x[i] * s);
            change = fmax(change, fabs(hn[i] - h[i]));
        }
        memcpy(h, hn, sizeof h);
        if (change < 1e-13) break;
    }
    double m1 = 0.0;
    for (int i = 0; i < GL_N; ++i) m1 += w[i] * h[i] * x[i];
    return 1.0 - 2.0 * sqrt(1.0 - omega) * m1;
}

static void check_vdhulst_budget(void)
{
    double x[GL_N], w[GL_N];
    tu_gauss_legendre(GL_N, 0.0, 1.0, x, w);
    /* The reference itself: omega = 1 conserves (r = 1). */
    check_close("H-function reference: r(omega = 1) = 1", exact_isotropic_albedo(1.0, x, w), 1.0, 1e-9);
    double v = 0.0;
    soak_vdhulst_albedo(0.5, 0.0, &v);
    check_close("van de Hulst at omega 0.5: -1.37 % (the issue's -1.4 %)", v / exact_isotropic_albedo(0.5, x, w) - 1.0,
                -0.0137, 0.0005);
    soak_vdhulst_albedo(0.8, 0.0, &v);
    check_close("van de Hulst at omega 0.8: -0.45 %", v / exact_isotropic_albedo(0.8, x, w) - 1.0, -0.0045, 0.0005);
    /* The error of the chain's wet/dry ratio: dry albedo R_d exact by
     * inversion, wet albedo q R_d from the formula at its own omega. */
    enum { NR = 30 };
    double R[NR], rel[NR];
    for (int i = 0; i < NR; ++i) {
        R[i] = 0.02 * pow(0.95 / 0.02, i / (NR - 1.0)); /* 0.02 .. 0.95 */
        double om = 0.0;
        soak_vdhulst_invert(R[i], 0.0, &om);
        rel[i] = exact_isotropic_albedo(om, x, w) / R[i]; /* exact / formula at that omega */
    }
    double worst = 0.0;
    for (int d = 0; d < NR; ++d)
        for (int q = 0; q < NR; ++q)
            if (R[q] <= R[d] && R[q] >= 0.3 * R[d] && R[q] >= 0.02) worst = fmax(worst, fabs(rel[q] / rel[d] - 1.0));
    printf("  van de Hulst: worst error of the wet/dry ratio %.3f %% (dry >= 0.02, ratio >= 0.3)\n", 100 * worst);
    check_true("van de Hulst's error on the wet/dry ratio within the stated 1.4 % budget", worst <= 0.014);
}

/* Presets without a measurement: (1 - g_wet) / (1 - g_dry) equals sand's
 * calibrated transport ratio (asphalt is the documented exception). */
static void check_rule(const soak_preset_db *db)
{
    const soak_preset *sand = soak_presets_find(db, "sand");
    if (!check_true("sand preset present", sand != NULL)) return;
    double t = (1 - soak_hg2_mean_cosine(&sand->phase_wet)) / (1 - soak_hg2_mean_cosine(&sand->phase_dry));
    check_close("sand transport ratio 0.519", t, 0.51875, 1e-12);
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        if (!soak_material_kind_porous(p->kind) || p->has_measured || strcmp(p->name, "asphalt") == 0) continue;
        double gd = soak_hg2_mean_cosine(&p->phase_dry), gw = soak_hg2_mean_cosine(&p->phase_wet);
        char what[120];
        snprintf(what, sizeof what, "%s: wet mean cosine by the transport-ratio rule", p->name);
        check_close(what, gw, 1 - t * (1 - gd), 0.005);
    }
}

/* Copper, Hagemann, Gudat & Kunz 1974 (DESY SR-74/7) Table 3 rows around
 * 450, 550, 650 nm: wavelength nm, n, k. */
static const double cu_table[][3] = {{442.8, 1.169, 2.36}, {476.9, 1.152, 2.50}, {539.1, 1.037, 2.59},
                                     {563.6, 0.826, 2.60}, {619.9, 0.272, 3.24}, {652.5, 0.214, 3.67}};

static void interp(const double (*t)[3], int rows, double lam, double *n, double *k)
{
    for (int i = 0; i + 1 < rows; ++i)
        if (t[i][0] <= lam && lam <= t[i + 1][0]) {
            double u = (lam - t[i][0]) / (t[i + 1][0] - t[i][0]);
            *n = t[i][1] + u * (t[i + 1][1] - t[i][1]);
            *k = t[i][2] + u * (t[i + 1][2] - t[i][2]);
            return;
        }
    *n = *k = NAN;
}

static void check_metals(const soak_preset_db *db)
{
    const soak_preset *cu = soak_presets_find(db, "copper"), *al = soak_presets_find(db, "aluminium");
    if (!check_true("copper and aluminium presets", cu && al)) return;
    const double lam[3] = {650.0, 550.0, 450.0};
    /* Linear-sRGB reflectances of Real-Time Rendering 3rd ed., Table 7.3. */
    const double cu_rgb[3] = {0.955, 0.638, 0.538}, al_rgb[3] = {0.913, 0.922, 0.924};
    for (int c = 0; c < 3; ++c) {
        double n, k;
        interp(cu_table, 6, lam[c], &n, &k);
        char what[120];
        snprintf(what, sizeof what, "copper n[%d] = measured table at %.0f nm", c, lam[c]);
        check_close(what, soak_rgb_at(cu->ior_n, c), n, 1e-4);
        snprintf(what, sizeof what, "copper k[%d] = measured table at %.0f nm", c, lam[c]);
        check_close(what, soak_rgb_at(cu->ior_k, c), k, 1e-4);
        snprintf(what, sizeof what, "copper F0[%d] vs measured colour %.3f", c, cu_rgb[c]);
        check_close(what, f0(soak_rgb_at(cu->ior_n, c), soak_rgb_at(cu->ior_k, c)), cu_rgb[c], 0.02);
        snprintf(what, sizeof what, "aluminium F0[%d] vs measured colour %.3f", c, al_rgb[c]);
        check_close(what, f0(soak_rgb_at(al->ior_n, c), soak_rgb_at(al->ior_k, c)), al_rgb[c], 0.01);
    }
    check_true("copper is orange: R - B > 0.35", cu->albedo.r - cu->albedo.b > 0.35);
}

/* Pope & Fry 1997, pure water absorption (1/m), 400 to 700 nm every 2.5 nm. */
static const double pope_fry[121] = {
    0.00663, 0.00579, 0.0053,  0.00503, 0.00473, 0.00452, 0.00444, 0.00442, 0.00454, 0.00474, 0.00478, 0.00482,
    0.00495, 0.00504, 0.0053,  0.0058,  0.00635, 0.00696, 0.00751, 0.0083,  0.00922, 0.00969, 0.00962, 0.00957,
    0.00979, 0.01005, 0.01011, 0.0102,  0.0106,  0.0109,  0.0114,  0.0121,  0.0127,  0.0131,  0.0136,  0.0144,
    0.015,   0.0162,  0.0173,  0.0191,  0.0204,  0.0228,  0.0256,  0.028,   0.0325,  0.0372,  0.0396,  0.0399,
    0.0409,  0.0416,  0.0417,  0.0428,  0.0434,  0.0447,  0.0452,  0.0466,  0.0474,  0.0489,  0.0511,  0.0537,
    0.0565,  0.0593,  0.0596,  0.0606,  0.0619,  0.064,   0.0642,  0.0672,  0.0695,  0.0733,  0.0772,  0.0836,
    0.0896,  0.0989,  0.11,    0.122,   0.1351,  0.1516,  0.1672,  0.1925,  0.2224,  0.247,   0.2577,  0.2629,
    0.2644,  0.2665,  0.2678,  0.2707,  0.2755,  0.281,   0.2834,  0.2904,  0.2916,  0.2995,  0.3012,  0.3077,
    0.3108,  0.322,   0.325,   0.335,   0.34,    0.358,   0.371,   0.393,   0.41,    0.424,   0.429,   0.436,
    0.439,   0.448,   0.448,   0.461,   0.465,   0.478,   0.486,   0.502,   0.516,   0.538,   0.559,   0.592,
    0.624};

/* Trapezoid average over [lo, hi] nm. */
static double band_average(double lo, double hi)
{
    double sum = 0.0;
    for (int i = 0; i < 120; ++i) {
        double a = 400.0 + 2.5 * i, b = a + 2.5;
        if (a >= lo && b <= hi) sum += 1.25 * (pope_fry[i] + pope_fry[i + 1]);
    }
    return sum / (hi - lo);
}

static void check_water(const soak_preset_db *db)
{
    const soak_liquid *w = soak_presets_find_liquid(db, "water");
    if (!check_true("water present", w != NULL)) return;
    check_close("water sigma_a R = Pope & Fry 600-700 nm average (1/m)", w->sigma_a_per_m.r, band_average(600, 700),
                1e-5);
    check_close("water sigma_a G = Pope & Fry 500-600 nm average (1/m)", w->sigma_a_per_m.g, band_average(500, 600),
                1e-5);
    check_close("water sigma_a B = Pope & Fry 400-500 nm average (1/m)", w->sigma_a_per_m.b, band_average(400, 500),
                1e-5);
    check_close("water index 1.333", w->ior, 1.333, 0);
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[512];
    if (!check_status("load shipped presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) {
        printf("%s\n", err);
        return check_finish();
    }
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    if (check_true("water", water != NULL)) check_measured(db, water);
    if (water) check_sun(db, water);
    if (water) check_riese(db, water);
    check_rule(db);
    check_vdhulst_budget();
    check_metals(db);
    check_water(db);
    soak_presets_free(db);
    return check_finish();
}
