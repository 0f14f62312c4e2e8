/* soak bake drops: raindrop impacts wetting a surface over time (model in
 * soak/bake_drops.h), an image sequence of wet maps. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_budget.h"
#include "bake_cli.h"
#include "bake_uv_cli.h"
#include "cli.h"
#include "soak/bake_drops.h"
#include "soak/bake_rain.h"
#include "soak/geometry.h"

#define CMD "bake drops"
#define DROPS_MAX_FPS 10000

typedef struct drops_job {
    soak_drops_params p;
    const char *mesh_path, *exposure_path;
    double fps, map_size;
    int have_fps, have_texel, have_map_size, rays, up_axis, no_wrap;
    soak_image exposure; /* pixels NULL without */
    soak_drops_state *state;
    bake_uv_opts uvo; /* MESH: --uv-set, --uv-outside, --strict */
} drops_job;

static const cli_choice axes[] = {{"x", 0, 0},  {"y", 1, 0},  {"z", 2, 0}, {"-x", 3, 0},
                                  {"-y", 4, 0}, {"-z", 5, 0}, {NULL, 0, 0}};

#define F(field) CLI_FIELD(drops_job, field)
static const cli_opt drops_opts[] = {
    {"--rate", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_DROP_RATE_MAX, F(p.rate_mm_h), .meta = "MM_H",
     .help = "rain rate, %R mm/h (default 10)" BAKE_DELIVERED_RATE_HELP},
    {"--duration", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_DROPS_MAX_TIME, F(p.duration), .meta = "S",
     .help = "seconds of rain from t = 0; then the surface dries (default 10)"},
    {"--texel", NULL, CLI_OPT_DOUBLE, .lo = 1e-9, .hi = SOAK_DROPS_MAX_SCALE, F(p.texel_m), CLI_SEEN(drops_job, have_texel),
     .meta = "M", .help = "metres per texel (default 0.001)"},
    {"--map-size", NULL, CLI_OPT_DOUBLE, .lo = 1e-9, .hi = 1e6, F(map_size), CLI_SEEN(drops_job, have_map_size),
     .meta = "M", .help = "or: the map's width in metres (texel = M / width)"},
    {"--capacity", NULL, CLI_OPT_DOUBLE, .lo = 1e-12, .hi = 1, F(p.capacity_m), .meta = "M",
     .help = "water depth of a fully wet texel (wet map 1), m (default 0.0002)"},
    {"--spread-factor", NULL, CLI_OPT_DOUBLE, .lo = 1, .hi = 100, F(p.spread_factor), .meta = "F",
     .help = "splat diameter / drop diameter (default: Clanet et al. 2004, 0.9 We^1/4)"},
    {"--min-drop", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_DROP_D_MAX_MM * 0.999, F(p.min_diameter_mm), .meta = "MM",
     .help = "ignore drops below this diameter, mm (default 0: all that land)"},
    {"--dry-time", NULL, CLI_OPT_DOUBLE, .lo = 1e-9, .hi = SOAK_DROPS_MAX_TIME, F(p.dry_time), .meta = "S",
     .help = "seconds the drying schedule takes after the rain (default 20)"},
    {"--t-fill", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(p.t_fill), .meta = "F",
     .help = "drying: pore emptying time, %R of --dry-time (default 0.2)"},
    {"--no-wrap", NULL, CLI_OPT_FLAG, .flag = 1, F(no_wrap),
     .help = "clip splats at the map's edges (default: wrap, a tiling plane;\nalways clipped with a mesh or --exposure)"},
    {"--splash", NULL, CLI_OPT_FLAG, .flag = 1, F(p.splash),
     .help = "drops on wet texels splash when We Oh^-0.4 exceeds Cossali et al.'s (1997)\n"
             "2100 + 5880 (h/D)^1.44, throwing Marmanis & Thoroddsen's (1996) number of\n"
             "secondary drops (default: off, every drop one splat)"},
    {"--splash-fraction", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(p.splash_fraction), .meta = "F",
     .help = "--splash: share of a splashing drop's volume thrown, %R (default 0.2)"},
    {"--splash-speed", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(p.splash_speed), .meta = "F",
     .help = "--splash: largest launch speed / impact speed, %R (default 0.2)"},
    {"--fps", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = DROPS_MAX_FPS, F(fps), CLI_SEEN(drops_job, have_fps), .meta = "N",
     .help = "frames per second: frame f is at t = f / N (default 24)"},
    {"--exposure", NULL, CLI_OPT_STRING, F(exposure_path), .meta = "PATH",
     .help = "sky exposure map (`soak bake rain --exposure`), same size"},
    {"--rays", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_RAIN_MAX_RAYS, F(rays), .meta = "N",
     .help = "MESH: exposure rays per texel, %R (default 64)"},
    {"--up", NULL, CLI_OPT_CHOICE, .choices = axes, F(up_axis), .meta = "x|y|z|-x|-y|-z",
     .help = "MESH: world up axis (default y)"},
};
#undef F

#define DROPS_TABLES(o, j, u) {BAKE_IMAGE_TABLE(o), CLI_TABLE(drops_opts, (j)), BAKE_UV_TABLE(u), BAKE_SEQUENCE_TABLE(o)}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake drops [MESH] [options] --frames A-B -o drops.%%04d.exr\n\n"
            "Wet maps of a surface during and after rain. Drops of the Marshall-Palmer (1948) size\n"
            "distribution fall at Atlas et al.'s (1973) terminal velocities: impacts per area and\n"
            "time n = int N(D) v(D) dD (3271 /m^2/s at 5 mm/h, 4451 at 10), a space-time Poisson\n"
            "process weighted by the sky exposure (MESH: computed as `soak bake rain` does; or\n"
            "--exposure; neither: an open plane). Each drop spreads its volume over a disc of\n"
            "Clanet et al.'s (2004) maximal spread, filling the texels up to --capacity; the wet\n"
            "map is depth / capacity, the wetness chain's liquid fraction. After --duration the\n"
            "map dries by the drying bake's pore schedule over --dry-time. Frame f is at time\n"
            "f / fps whatever --frames range is baked, so chunks equal one run; same seed, same\n"
            "bytes on any number of threads. Without --frames one map at --time (default: the\n"
            "rain's end). Frame 0 is at t = 0 unless --time / --frame-origin say otherwise.\n\n"
            "options:\n");
    cli_opt seq[BAKE_SHARED_OPTS_MAX];
    size_t n = bake_table_help(bake_sequence_opts, bake_sequence_opts_n, seq, "--frame-origin", BAKE_ORIGIN_ZERO_HELP);
    const cli_opt_table tables[] = {BAKE_IMAGE_TABLE(NULL), CLI_TABLE(drops_opts, NULL), BAKE_UV_TABLE(NULL), {seq, n, NULL}};
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    bake_uv_formats_help(out);
    fprintf(out, "\nexample:\n"
                 "  soak bake drops --rate 10 --map-size 1 --duration 8 --frames 0-239 --fps 24 -o drops.%%04d.exr\n");
}

static int mesh_arg(void *ctx, const char *arg)
{
    drops_job *j = ctx;
    if (j->mesh_path) {
        cli_error(CMD, "unexpected argument '%s' (one mesh only)", arg);
        return 0;
    }
    j->mesh_path = arg;
    return 1;
}

/* Exposure of MESH by the rain bake with no water (duration 0). */
static int mesh_exposure(drops_job *j, const bake_opts *o)
{
    char err[4352] = "";
    soak_mesh mesh;
    soak_status st = soak_mesh_load_uv(j->mesh_path, &j->uvo.uv, &mesh, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    soak_rain_params rp;
    soak_rain_defaults(&rp);
    double s = j->up_axis < 3 ? 1.0 : -1.0;
    int k = j->up_axis % 3;
    rp.up = soak_v3(k == 0 ? s : 0, k == 1 ? s : 0, k == 2 ? s : 0);
    rp.rain_dir = rp.up;
    rp.duration = 0;
    rp.rays = j->rays;
    rp.seed = o->seed;
    rp.uv.outside = (soak_uv_outside)j->uvo.outside;
    soak_rain_result res;
    soak_bake_exec exec = {(int)o->threads, NULL, NULL};
    st = soak_bake_rain(&mesh, (int)o->width, (int)o->height, &rp, &exec, &res, err, sizeof err);
    soak_mesh_free(&mesh);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s: %s", j->mesh_path, err[0] ? err : soak_status_str(st));
        return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    }
    j->exposure = res.exposure;
    res.exposure.pixels = NULL;
    soak_rain_result_free(&res);
    if (bake_uv_verdict(CMD, j->mesh_path, &res.uv, &j->uvo) ||
        bake_uv_dry_verdict(CMD, j->mesh_path, &j->exposure, &res.uv, &j->uvo))
        return SOAK_EXIT_FAIL;
    bake_uv_report(j->mesh_path, &res.uv);
    return 0;
}

/* --exposure: one channel (luma of RGB), the map's size. */
static int read_exposure(drops_job *j, bake_opts *o)
{
    char err[4352] = "";
    soak_image img;
    soak_status st = soak_image_read(j->exposure_path, &img, err, sizeof err);
    if (st != SOAK_OK) return bake_fail(CMD, st == SOAK_ERR_ARG ? SOAK_ERR_IO : st, err);
    if ((o->have_width && o->width != img.width) || (o->have_height && o->height != img.height)) {
        cli_error(CMD, "--width/--height %ldx%ld do not match --exposure %s (%dx%d)", o->width, o->height,
                  j->exposure_path, img.width, img.height);
        soak_image_free(&img);
        return SOAK_EXIT_USAGE;
    }
    o->width = img.width, o->height = img.height;
    st = soak_image_alloc(&j->exposure, img.width, img.height, 1);
    for (size_t i = 0; st == SOAK_OK && i < (size_t)img.width * img.height; ++i) {
        double v = soak_mask_value(&img, i);
        if (!soak_in_range(v, 0, 1e6)) {
            cli_error(CMD, "--exposure %s: texel %zu is %g (expected a finite value >= 0)", j->exposure_path, i, v);
            st = SOAK_ERR_ARG;
        }
        j->exposure.pixels[i] = (float)v;
    }
    soak_image_free(&img);
    return st == SOAK_OK ? 0 : (st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL);
}

static soak_status frame(void *vctx, int f, double time, const soak_bake_exec *exec, soak_image *out, char *err,
                         size_t errlen)
{
    drops_job *j = vctx;
    char label[32];
    soak_status st = soak_drops_frame(j->state, time, exec, out);
    if (st != SOAK_OK)
        snprintf(err, errlen, "%s at %g s: %s", bake_frame_label(f, label, sizeof label), time, soak_status_str(st));
    return st;
}

/* Settings the options leave open; returns 0 or the exit code. */
static int settle(drops_job *j, bake_opts *o)
{
    if (j->have_texel && j->have_map_size) {
        cli_error(CMD, "--texel and --map-size: give one");
        return SOAK_EXIT_USAGE;
    }
    if (j->have_map_size) j->p.texel_m = j->map_size / (double)o->width;
    if (!soak_in_range(j->p.texel_m, 1e-9, SOAK_DROPS_MAX_SCALE)) {
        cli_error(CMD, "--map-size: %g m over %ld texels is outside 1e-9..%g m per texel", j->map_size, o->width,
                  SOAK_DROPS_MAX_SCALE);
        return SOAK_EXIT_USAGE;
    }
    if (j->have_fps) o->frame_time = 1.0 / j->fps;
    if (isnan(o->time)) o->time = o->have_frames ? 0 : j->p.duration;
    if (o->have_frames && !o->have_origin) o->origin = 0, o->have_origin = 1;
    j->p.seed = o->seed;
    j->p.wrap = !(j->no_wrap || j->mesh_path || j->exposure_path);
    if (j->mesh_path && j->exposure_path) {
        cli_error(CMD, "MESH and --exposure: give one (the mesh's exposure is computed)");
        return SOAK_EXIT_USAGE;
    }
    return 0;
}

int soak_bake_drops_main(int argc, char **argv)
{
    bake_opts o;
    bake_opts_init(&o, CMD, NAN, 1.0 / 24);
    drops_job j;
    memset(&j, 0, sizeof j);
    soak_drops_defaults(&j.p);
    j.rays = 64, j.up_axis = 1;
    const cli_spec spec = BAKE_SPEC(CMD, usage, mesh_arg, &j);
    bake_uv_opts_init(&j.uvo);
    const cli_opt_table tables[] = DROPS_TABLES(&o, &j, &j.uvo);
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    if (rc >= 0) return rc;
    if ((rc = settle(&j, &o)) != 0) return rc;
    const char *inputs[2] = {j.mesh_path ? j.mesh_path : j.exposure_path, j.exposure_path};
    if ((rc = bake_opts_check(&o, inputs, inputs[0] ? 1 : 0)) != 0 ||
        (rc = bake_check_times(&o, 0, SOAK_DROPS_MAX_TIME)) != 0)
        return rc;
    if (j.mesh_path) rc = mesh_exposure(&j, &o);
    else if (j.exposure_path) rc = read_exposure(&j, &o);
    double last_time = fmax(bake_frame_time(&o, o.have_frames ? o.first : -1), bake_frame_time(&o, o.last));
    if (rc == 0 && (rc = settle(&j, &o)) == 0 &&
        (rc = bake_drops_budget(CMD, &j.p, o.width, o.height, o.have_frames ? o.last - o.first + 1 : 1,
                                o.have_frames ? last_time : o.time)) == 0) {
        soak_status st = soak_drops_create(&j.p, j.exposure.pixels ? &j.exposure : NULL, (int)o.width, (int)o.height,
                                           &j.state);
        rc = st == SOAK_OK ? bake_run(&o, frame, &j) : bake_fail(CMD, st, "invalid drops settings");
    }
    soak_drops_destroy(j.state);
    soak_image_free(&j.exposure);
    return rc;
}
