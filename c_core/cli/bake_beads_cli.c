/* soak bake beads: rain standing as beads on surfaces of high contact
 * angle, a normal + height map (model in soak/bake_beads.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "bake_cli.h"
#include "cli.h"
#include "soak/bake_beads.h"
#include "soak/bake_drops.h"
#include "soak/preset.h"

#define CMD "bake beads"

typedef struct beads_job {
    soak_beads_params p;
    const char *preset, *materials;
    double bead_above;
    int have_angle, width, height;
    soak_beads_stats stats;
    int flat; /* the angle is below --bead-above: a film, the map is flat */
} beads_job;

#define F(field) CLI_FIELD(beads_job, field)
static const cli_opt beads_opts[] = {
    {"--preset", NULL, CLI_OPT_STRING, F(preset), .meta = "NAME",
     .help = "take the contact angle of this preset (soak materials; wetting.contact_angle_deg)"},
    {"--materials", NULL, CLI_OPT_STRING, F(materials), .meta = "PATH",
     .help = "presets file for --preset (default: $SOAK_MATERIALS or the shipped one)"},
    {"--contact-angle", NULL, CLI_OPT_DOUBLE, .lo = SOAK_BEAD_ANGLE_MIN, .hi = SOAK_BEAD_ANGLE_MAX,
     F(p.contact_angle_deg), CLI_SEEN(beads_job, have_angle), .meta = "DEG",
     .help = "water's contact angle, %R deg (default: the preset's; 90 without --preset)"},
    {"--bead-above", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 180, F(bead_above), .meta = "DEG",
     .help = "beads form above this contact angle; below it water is a film and\nthe map is flat (default 60)"},
    {"--rate", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = SOAK_DROP_RATE_MAX, F(p.rate_mm_h), .meta = "MM_H",
     .help = "rain rate, (0, 500] mm/h (default 10)" BAKE_DELIVERED_RATE_HELP},
    {"--duration", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_DROPS_MAX_TIME, F(p.duration), .meta = "S",
     .help = "seconds of rain (default 10)"},
    {"--texel", NULL, CLI_OPT_DOUBLE, .lo = 1e-9, .hi = SOAK_DROPS_MAX_SCALE, F(p.texel_m), .meta = "M",
     .help = "metres per texel (default 0.00025)"},
    {"--min-drop", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_DROP_D_MAX_MM * 0.999, F(p.min_diameter_mm), .meta = "MM",
     .help = "ignore drops below this diameter, mm (default 0: all that land)"},
    {"--height-range", NULL, CLI_OPT_DOUBLE, .lo = 1e-12, .hi = 1, F(p.height_range_m), .meta = "M",
     .help = "bead height stored as alpha 1, m (default 0.006; a puddle of water\nstands at most 2 l_c = 5.4 mm)"},
    {"--supersample", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_BEADS_MAX_SUPERSAMPLE, F(p.supersample), .meta = "N",
     .help = "points per texel side averaged, %R (default 4)"},
};
#undef F

static const cli_opt float_opt[] = {
    {"--float", NULL, CLI_OPT_FLAG, .flag = 1, CLI_FIELD(bake_opts, float_exr), .help = "32-bit EXR instead of half"},
};

static void usage(FILE *out)
{
    fprintf(out, "usage: soak bake beads [--preset NAME | --contact-angle DEG] [options] -o beads.exr\n\n"
                 "Rain on a smooth or water-repellent surface (glass, paint, waxed wood, leaves) stands as\n"
                 "beads. The drops of `soak bake drops` (same --seed, --rate, --texel: same drops) land as\n"
                 "spherical caps of their own volume at the contact angle theta: h / r = tan(theta / 2),\n"
                 "V = pi h (3 r^2 + h^2) / 6 (de Gennes, Brochard-Wyart, Quere 2004); beads that touch\n"
                 "coalesce (volume and centre of mass kept). The map tiles. RGBA: RGB = (n + 1) / 2, the\n"
                 "normal in tangent space, v up (Blender/OpenGL); A = height / --height-range. Output:\n"
                 ".exr or .tif (PNG would store colour divided by alpha: refused). Below --bead-above the\n"
                 "water is a film (soak bake drops / rain) and the map is flat, which the bake says.\n\n"
                 "options:\n");
    cli_opt img[BAKE_SHARED_OPTS_MAX];
    size_t n = bake_table_help(bake_image_opts, bake_image_opts_n, img, "--output",
                               "output map: .exr (half) or .tif (16-bit linear), .tx");
    const cli_opt_table tables[] = {{img, n, NULL}, {float_opt, 1, NULL}, CLI_TABLE(beads_opts, NULL)};
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    fprintf(out, "\nexample:\n"
                 "  soak bake beads --preset copper --duration 30 --width 1024 -o beads.exr\n"
                 "  soak bake beads --contact-angle 160 --rate 5 -o lotus.exr   # a lotus leaf\n");
}

static soak_status frame(void *vctx, int f, double time, const soak_bake_exec *exec, soak_image *out, char *err,
                         size_t errlen)
{
    (void)f, (void)time;
    beads_job *j = vctx;
    if (j->flat) j->p.duration = 0; /* no drops: a flat normal, zero height */
    soak_status st = soak_beads_bake(&j->p, j->width, j->height, exec, out, &j->stats);
    if (st != SOAK_OK) snprintf(err, errlen, "the map: %s", soak_status_str(st));
    return st;
}

static int angle_from_preset(beads_job *j)
{
    char err[4352] = "";
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(j->materials, &db, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "--preset: %s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    const soak_preset *p = soak_presets_find(db, j->preset);
    int rc = 0;
    if (!p) {
        cli_error(CMD, "--preset: no preset named '%s' in %s (see soak materials)", j->preset, soak_presets_path(db));
        rc = SOAK_EXIT_USAGE;
    } else if (!(p->contact_angle_deg >= 0)) {
        cli_error(CMD, "--preset %s: %s gives no wetting.contact_angle_deg; give --contact-angle", j->preset,
                  soak_presets_path(db));
        rc = SOAK_EXIT_USAGE;
    } else if (!j->have_angle) {
        j->p.contact_angle_deg =
            p->contact_angle_deg < SOAK_BEAD_ANGLE_MIN ? SOAK_BEAD_ANGLE_MIN : p->contact_angle_deg;
    }
    soak_presets_free(db);
    return rc;
}

static int refuse_png(const bake_opts *o)
{
    const char *dot = o->output ? strrchr(o->output, '.') : NULL;
    if (dot && strcasecmp(dot, ".png") == 0) {
        cli_error(CMD,
                  "-o %s: a PNG stores colour divided by alpha, which would break the normal under the height; "
                  "write .exr or .tif",
                  o->output);
        return SOAK_EXIT_USAGE;
    }
    return 0;
}

static void report(const beads_job *j)
{
    if (j->flat) {
        fprintf(stderr,
                "soak bake beads: contact angle %g deg is below --bead-above %g deg: water stands as a film "
                "here (soak bake drops / rain); the map is flat (no beads)\n",
                j->p.contact_angle_deg, j->bead_above);
        return;
    }
    const soak_beads_stats *s = &j->stats;
    fprintf(stderr, "soak bake beads: %zu drops -> %zu beads at %g deg, %.4g mm^3 of water, largest bead r = %.2f mm",
            s->drops, s->beads, j->p.contact_angle_deg, s->bead_volume_m3 * 1e9, s->largest_contact_radius_m * 1e3);
    if (s->beyond_capillary)
        fprintf(stderr, "; %zu beads wider than the capillary length 2.7 mm (gravity would flatten them)",
                s->beyond_capillary);
    if (s->clipped_texels) fprintf(stderr, "; %zu texels above --height-range clipped", s->clipped_texels);
    fprintf(stderr, "\n");
}

int soak_bake_beads_main(int argc, char **argv)
{
    bake_opts o;
    bake_opts_init(&o, CMD, 0, 0);
    beads_job j;
    memset(&j, 0, sizeof j);
    soak_beads_defaults(&j.p);
    j.bead_above = 60;
    const cli_spec spec = BAKE_SPEC(CMD, usage, NULL, &j);
    const cli_opt_table tables[] = {BAKE_IMAGE_TABLE(&o), {float_opt, 1, &o}, CLI_TABLE(beads_opts, &j)};
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    if (rc >= 0) return rc;
    if (j.materials && !j.preset) {
        cli_error(CMD, "--materials needs --preset");
        return SOAK_EXIT_USAGE;
    }
    if ((rc = refuse_png(&o)) != 0 || (rc = bake_opts_check(&o, NULL, 0)) != 0) return rc;
    if (j.preset && (rc = angle_from_preset(&j)) != 0) return rc;
    j.p.seed = o.seed;
    j.width = (int)o.width, j.height = (int)o.height;
    j.flat = !(j.p.contact_angle_deg > j.bead_above);
    if (soak_beads_check(&j.p) != SOAK_OK) return bake_fail(CMD, SOAK_ERR_ARG, "invalid bead settings");
    /* the drops are held in memory: refuse before drawing them */
    const double area = (double)o.width * j.p.texel_m * (double)o.height * j.p.texel_m;
    const double expected =
        soak_drop_flux(j.p.rate_mm_h, j.p.min_diameter_mm, SOAK_DROP_D_MAX_MM) * area * j.p.duration;
    if (!j.flat && !(expected <= 0.5 * SOAK_BEADS_MAX_DROPS)) {
        cli_error(CMD,
                  "about %.3g drops expected (--rate x map area x --duration) is above the %.3g this bake holds; "
                  "shorten --duration or bake a smaller map",
                  expected, 0.5 * SOAK_BEADS_MAX_DROPS);
        return SOAK_EXIT_USAGE;
    }
    rc = bake_run(&o, frame, &j);
    if (rc == 0) report(&j);
    return rc;
}
