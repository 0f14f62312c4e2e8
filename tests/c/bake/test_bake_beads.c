/* Beads against independent references: the cap's contact angle read back
 * as the slope of its own surface at the contact line, its radius and
 * height against a sphere of radius R (r = R sin theta, h = R (1 - cos
 * theta)), its volume against a numerical integral of disc slices, the
 * hemisphere at 90 deg (V = 2/3 pi r^3); a baked single bead's peak height,
 * outline area and column volume against those formulas (and pi R^3 (2/3 -
 * cos theta) when it overhangs); coalescence conserving volume and the
 * centre of mass; a rain bake whose map holds the volume of the rain's own
 * drops (drawn here by soak_drops_impacts); normals pointing outwards in
 * tangent space, v up; bad input refused. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "soak/bake_beads.h"
#include "soak/bake_drops.h"

#define PI 3.14159265358979323846

/* pi int_{R-h}^{R} (R^2 - z^2) dz by Simpson's rule, written from the
 * sphere alone. */
static double slice_volume(double R, double h)
{
    const int n = 2000;
    double a = R - h, dz = h / n, sum = 0;
    for (int i = 0; i <= n; ++i) {
        double z = a + i * dz, f = PI * (R * R - z * z);
        sum += f * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
    }
    return sum * dz / 3;
}

static void test_cap(void)
{
    const double V = 4.0e-9; /* 4 mm^3, a 2 mm drop */
    const double angles[] = {5, 20, 45, 70, 90, 110, 150, 170};
    double worst_angle = 0, worst_geom = 0, worst_vol = 0;
    for (size_t k = 0; k < sizeof angles / sizeof angles[0]; ++k) {
        soak_bead_shape b;
        if (!check_status("cap", soak_bead_cap(V, angles[k], &b), SOAK_OK)) return;
        double th = angles[k] * PI / 180, R = b.sphere_radius_m;
        worst_geom = fmax(worst_geom, fabs(b.contact_radius_m / (R * sin(th)) - 1));
        worst_geom = fmax(worst_geom, fabs(b.height_m / (R * (1 - cos(th))) - 1));
        worst_vol = fmax(worst_vol, fabs(slice_volume(R, b.height_m) / V - 1));
        if (angles[k] < 90) { /* the slope just inside the contact line is tan(theta) */
            double e = 1e-7 * b.contact_radius_m, r = b.contact_radius_m;
            double slope = (soak_bead_surface(&b, r - 2 * e) - soak_bead_surface(&b, r - e)) / e;
            worst_angle = fmax(worst_angle, fabs(atan(slope) * 180 / PI - angles[k]));
        }
    }
    check_close("contact angle = atan of the surface's slope at the contact line, worst deg", worst_angle, 0, 1e-3);
    check_close("r = R sin(theta), h = R (1 - cos(theta)), worst relative", worst_geom, 0, 1e-12);
    check_close("V = pi int (R^2 - z^2) dz (Simpson), worst relative", worst_vol, 0, 1e-9);
    soak_bead_shape half;
    soak_bead_cap(V, 90, &half);
    check_rel("90 deg: a hemisphere, r = cbrt(3 V / (2 pi))", half.contact_radius_m, cbrt(3 * V / (2 * PI)), 1e-12);
    check_rel("90 deg: h = r", half.height_m, half.contact_radius_m, 1e-12);
    soak_bead_shape b;
    check_status("0 deg refused", soak_bead_cap(V, 0, &b), SOAK_ERR_ARG);
    check_status("180 deg refused", soak_bead_cap(V, 180, &b), SOAK_ERR_ARG);
    check_status("NaN angle refused", soak_bead_cap(V, NAN, &b), SOAK_ERR_ARG);
    check_status("zero volume refused", soak_bead_cap(0, 90, &b), SOAK_ERR_ARG);
}

static double map_volume(const soak_image *img, const soak_beads_params *p)
{
    double sum = 0;
    for (size_t i = 0; i < (size_t)img->width * img->height; ++i) sum += img->pixels[4 * i + 3];
    return sum * p->height_range_m * p->texel_m * p->texel_m;
}

static void single_bead(double theta_deg)
{
    soak_beads_params p;
    soak_beads_defaults(&p);
    p.texel_m = 5e-5, p.contact_angle_deg = theta_deg, p.supersample = 8;
    const double V = PI * 8e-9 / 6; /* a 2 mm drop */
    soak_bead_drop d = {64.5, 64.5, V};
    soak_image img = {0, 0, 0, NULL};
    soak_beads_stats st;
    if (!check_status("single bead", soak_beads_from_drops(&p, 128, 128, &d, 1, NULL, &img, &st), SOAK_OK)) return;
    double th = theta_deg * PI / 180, t = tan(th / 2);
    double r = cbrt(6 * V / (PI * t * (3 + t * t))), h = t * r, R = r / sin(th), outline = theta_deg <= 90 ? r : R;
    double column = theta_deg <= 90 ? V : PI * R * R * R * (2.0 / 3 - cos(th));
    char what[160];
    snprintf(what, sizeof what, "%g deg: peak height = h = r tan(theta/2) (centre texel mean)", theta_deg);
    check_rel(what, img.pixels[4 * (64 * 128 + 64) + 3] * p.height_range_m, h, 2e-3);
    size_t wet = 0;
    for (size_t i = 0; i < 128 * 128; ++i) wet += img.pixels[4 * i + 3] > 0;
    /* texels touched by a disc of radius a: their centres lie within a +- half a diagonal */
    double lo = PI * pow(outline - 0.7072 * p.texel_m, 2), hi = PI * pow(outline + 0.7072 * p.texel_m, 2);
    double area = wet * p.texel_m * p.texel_m;
    snprintf(what, sizeof what, "%g deg: texels with water = pi outline^2 within half a texel diagonal", theta_deg);
    check_true(what, area > lo && area < hi);
    printf("  outline area %.4g mm^2 in [%.4g, %.4g]\n", area * 1e6, lo * 1e6, hi * 1e6);
    snprintf(what, sizeof what, "%g deg: map column volume = %s", theta_deg,
             theta_deg <= 90 ? "V" : "pi R^3 (2/3 - cos theta)");
    check_rel(what, map_volume(&img, &p), column, 3e-3);
    const float *right = img.pixels + 4 * (64 * 128 + 64 + (int)(0.5 * outline / p.texel_m));
    const float *up = img.pixels + 4 * ((64 - (int)(0.5 * outline / p.texel_m)) * 128 + 64);
    check_true("normal right of the centre leans +u, above it +v (tangent space, v up)",
               right[0] > 0.55f && fabsf(right[1] - 0.5f) < 0.01f && up[1] > 0.55f && fabsf(up[0] - 0.5f) < 0.01f);
    soak_image_free(&img);
}

static void test_coalescence(void)
{
    soak_beads_params p;
    soak_beads_defaults(&p);
    p.texel_m = 1e-4, p.contact_angle_deg = 80;
    soak_bead_shape s;
    soak_bead_cap(1e-9, 80, &s);
    double gap = 1.9 * s.outline_m / p.texel_m; /* two equal beads closer than 2 outlines touch */
    soak_bead_drop d[3] = {{40, 40, 1e-9}, {40 + gap, 40, 1e-9}, {40, 100, 3e-9}};
    soak_image img = {0, 0, 0, NULL};
    soak_beads_stats st;
    check_status("three drops", soak_beads_from_drops(&p, 128, 128, d, 3, NULL, &img, &st), SOAK_OK);
    check_true("two touching drops coalesce, the far one stays: 2 beads", st.beads == 2);
    check_rel("volume conserved by coalescence", st.bead_volume_m3, 5e-9, 1e-12);
    double mx = 0, w = 0;
    for (int x = 0; x < 128; ++x)
        for (int y = 20; y < 60; ++y)
            mx += x * (double)img.pixels[4 * (y * 128 + x) + 3], w += img.pixels[4 * (y * 128 + x) + 3];
    check_close("merged bead at the centre of mass (texels)", mx / w + 0.5, 40 + gap / 2, 0.05);
    /* across the wrapping edge: drops at x = 1 and x = 127 - gap + 2 touch through it */
    soak_bead_drop e[2] = {{1, 64, 1e-9}, {129 - gap, 64, 1e-9}};
    soak_image_free(&img);
    check_status("wrap", soak_beads_from_drops(&p, 128, 128, e, 2, NULL, &img, &st), SOAK_OK);
    check_true("drops touching across the map's edge coalesce (the map tiles)", st.beads == 1);
    soak_image_free(&img);
}

static void test_rain(void)
{
    soak_beads_params p;
    soak_beads_defaults(&p);
    p.contact_angle_deg = 85, p.duration = 20, p.rate_mm_h = 25, p.seed = 7;
    soak_image img = {0, 0, 0, NULL};
    soak_beads_stats st;
    if (!check_status("rain bake", soak_beads_bake(&p, 256, 256, NULL, &img, &st), SOAK_OK)) return;
    soak_drops_params dp;
    soak_drops_defaults(&dp);
    dp.seed = 7, dp.rate_mm_h = 25, dp.texel_m = p.texel_m, dp.duration = 20;
    soak_drop_impact *imp = NULL;
    size_t n = 0;
    soak_drops_impacts(&dp, NULL, 256, 256, 0, (long)ceil(20 / SOAK_DROPS_SLAB), &imp, &n);
    double vol = 0;
    size_t drops = 0;
    for (size_t i = 0; i < n; ++i)
        if (imp[i].t < 20) vol += PI * pow(imp[i].d_mm * 1e-3, 3) / 6, ++drops;
    free(imp);
    printf("  %zu drops -> %zu beads, largest r %.2f mm, %zu beyond l_c\n", st.drops, st.beads,
           st.largest_contact_radius_m * 1e3, st.beyond_capillary);
    check_true("every drop of the rain (soak_drops_impacts) lands", st.drops == drops && drops > 100);
    check_rel("beads hold the drops' volume (sum over beads)", st.bead_volume_m3, vol, 1e-9);
    check_rel("the map's column volume = the drops' volume (85 deg: no overhang)", map_volume(&img, &p), vol, 0.01);
    check_true("drops coalesced: fewer beads than drops", st.beads < st.drops);
    soak_image again = {0, 0, 0, NULL};
    soak_beads_bake(&p, 256, 256, NULL, &again, NULL);
    check_true("same seed, same map", memcmp(img.pixels, again.pixels, sizeof(float) * 4 * 256 * 256) == 0);
    p.contact_angle_deg = NAN;
    check_status("NaN contact angle refused", soak_beads_bake(&p, 256, 256, NULL, &again, NULL), SOAK_ERR_ARG);
    soak_image_free(&img), soak_image_free(&again);
}

int main(void)
{
    test_cap();
    single_bead(80);
    single_bead(150);
    test_coalescence();
    test_rain();
    return check_finish();
}
