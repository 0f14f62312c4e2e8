/* [Hnat06] (Hnat et al. 2006), Fig. 5: "when alpha_poro increases, surface
 * becomes darker and more specular". The flowerpot sweep's set-up
 * (scenes/povray/flowerpot_porosity.pov): one terracotta colour
 * (0.555, 0.212, 0.11), pores just full (wetness = porosity, no film), under
 * the scene's sun (direction (-0.4, -0.8, 0.8): cos 0.667); the porous clay
 * preset with its porosity swept 0.05 ... 0.55. Asserted:
 *  - darker: the wet diffuse luminance (soak_wetness_albedo_sun, without the
 *    liquid's mirror) falls strictly with porosity;
 *  - more specular: the water's mirror weight (Merillou/Hnat, porosity x fill)
 *    rises strictly;
 *  - visibly: the wet pots at the ends of the sweep differ by more than
 *    Delta E*ab 2.3, the just-noticeable difference (Mahy, Van Eycken &
 *    Oosterlinck 1994, Color Res. Appl. 19(2)), in CIELAB of linear Rec. 709
 *    under D65. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "soak/preset.h"
#include "soak/wetness.h"

#define N_SWEEP 6

static double lab_f(double t) { return t > 0.008856 ? cbrt(t) : 7.787 * t + 16.0 / 116; }

static void to_lab(soak_rgb c, double lab[3])
{
    double X = 0.4124 * c.r + 0.3576 * c.g + 0.1805 * c.b, Y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    double Z = 0.0193 * c.r + 0.1192 * c.g + 0.9505 * c.b;
    double fx = lab_f(X / 0.95047), fy = lab_f(Y), fz = lab_f(Z / 1.08883);
    lab[0] = 116 * fy - 16, lab[1] = 500 * (fx - fy), lab[2] = 200 * (fy - fz);
}

static double delta_e(soak_rgb a, soak_rgb b)
{
    double la[3], lb[3];
    to_lab(a, la);
    to_lab(b, lb);
    return sqrt((la[0] - lb[0]) * (la[0] - lb[0]) + (la[1] - lb[1]) * (la[1] - lb[1]) + (la[2] - lb[2]) * (la[2] - lb[2]));
}

static double lum(soak_rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

/* The wet pot at porosity a: its diffuse colour and the water's mirror weight. */
static int wet_pot(const soak_preset *clay, const soak_liquid *water, double a, soak_rgb *dry, soak_rgb *wet, double *mirror)
{
    const double cos_sun = 0.8 / 1.2;
    soak_preset p = *clay;
    p.porosity = a;
    p.albedo = soak_rgb3(0.555, 0.212, 0.11);
    soak_wet_params d, w;
    soak_wet_input in0 = soak_wet_input_steady(&p, 0.0), in1 = soak_wet_input_steady(&p, a);
    soak_rgb total;
    if (soak_preset_derive(&p) != SOAK_OK || soak_wetness_eval(&p, water, &in0, &d) != SOAK_OK ||
        soak_wetness_eval(&p, water, &in1, &w) != SOAK_OK ||
        soak_wetness_albedo_sun(&p, water, &d, cos_sun, dry, &total) != SOAK_OK ||
        soak_wetness_albedo_sun(&p, water, &w, cos_sun, wet, &total) != SOAK_OK)
        return 0;
    *mirror = w.water_specular_weight;
    return 1;
}

int main(void)
{
    soak_preset_db *db = NULL;
    char err[256];
    if (!check_status("presets", soak_presets_load(NULL, &db, err, sizeof err), SOAK_OK)) return check_finish();
    const soak_preset *clay = soak_presets_find(db, "clay");
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    soak_rgb dry[N_SWEEP], wet[N_SWEEP];
    double mirror[N_SWEEP];
    int ok = check_true("clay and water presets", clay && water);
    for (int i = 0; ok && i < N_SWEEP; ++i) {
        double a = 0.05 + 0.1 * i;
        ok = check_true("chain evaluates the pot", wet_pot(clay, water, a, &dry[i], &wet[i], &mirror[i]));
        if (ok)
            printf("  porosity %.2f: wet/dry luminance %.3f, Delta E dry-wet %.1f, water mirror weight %.2f\n", a,
                   lum(wet[i]) / lum(dry[i]), delta_e(dry[i], wet[i]), mirror[i]);
    }
    if (ok) {
        int darker = 1, glossier = 1;
        for (int i = 1; i < N_SWEEP; ++i) {
            darker &= lum(wet[i]) < lum(wet[i - 1]);
            glossier &= mirror[i] > mirror[i - 1];
        }
        check_true("wet pots darker with porosity ([Hnat06] Fig. 5)", darker);
        check_true("wet pots more specular with porosity: the water's mirror weight rises", glossier);
        double de = delta_e(wet[0], wet[N_SWEEP - 1]);
        char what[160];
        snprintf(what, sizeof what, "ends of the sweep visibly apart: Delta E*ab %.1f > 2.3 (JND)", de);
        printf("  %s\n", what);
        check_true(what, de > 2.3);
    }
    soak_presets_free(db);
    return check_finish();
}
