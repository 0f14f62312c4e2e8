/* soak bake rain: rain wetting of a mesh baked into its UV texture (model in
 * soak/bake_rain.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"
#include "soak/bake_rain.h"
#include "soak/geometry.h"
#include "soak/staged.h"

#define CMD "bake rain"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake rain MESH -o OUT [options]\n\n"
            "Rain wet map of a mesh (OBJ, PLY, glTF/GLB...; it must have UVs) at a texture\n"
            "resolution: per-texel sky exposure by ray casting through the mesh (Embree), drop\n"
            "impacts as a Poisson process with a splat kernel, evaporation, and downhill flow\n"
            "that fills concave upward-facing regions (puddles). Lengths in the mesh unit\n"
            "(metres), times in seconds. Same seed, same bytes, on any number of threads.\n\n"
            "options:\n"
            "  -o, --output PATH     wetness map (.exr/.png/.tif/.tx), w = 1 - exp(-depth/saturation)\n"
            "  --exposure PATH       also write the sky exposure (1 = open horizontal surface)\n"
            "  --water PATH          also write the water depth (m)\n"
            "  --width N, --height N texture size, 1..16384 (default 1024)\n"
            "  --rays N              rays per texel (default 64)\n"
            "  --sky rain|hemisphere rain cone (default) or cosine hemisphere (ambient occlusion)\n"
            "  --up x|y|z|-x|-y|-z   world up axis (default y, the OBJ/glTF convention)\n"
            "  --rain-dir X,Y,Z      direction the rain comes from (default: up)\n"
            "  --spread DEG          rain cone half-angle, 0..89 (default 10)\n"
            "  --duration S          seconds of rain, 0 = exposure only (default 600)\n"
            "  --steps N             time steps (default 32)\n"
            "  --rainfall MM_H       rainfall, mm/h (default 10)\n"
            "  --drop-size M         drop diameter, m (default 0.002)\n"
            "  --splat M             splat kernel standard deviation, m (default 0.002)\n"
            "  --evaporation MM_H    evaporation, mm/h (default 0.5)\n"
            "  --retention M         film kept on a flat surface, m (default 0.0002)\n"
            "  --saturation M        depth giving wetness 1 - 1/e, m (default 0.0002)\n"
            "  --flow-iterations N   routing sweeps per step (default 16)\n"
            "  --gutter N            texels of padding around UV islands (default 4)\n"
            "  --seed N, --threads N\n\n"
            "example:\n"
            "  soak bake rain statue.glb --width 2048 --height 2048 --rays 64 --duration 1800 \\\n"
            "       --exposure exposure.exr -o rain_wet.exr\n");
}

static int parse_vec(const char *opt, const char *text, soak_vec3 *out)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", text);
    char *c1 = strchr(buf, ','), *c2 = c1 ? strchr(c1 + 1, ',') : NULL;
    if (!c1 || !c2 || strchr(c2 + 1, ',')) {
        cli_error(CMD, "%s: expected X,Y,Z, got '%s'", opt, text);
        return 0;
    }
    *c1 = *c2 = '\0';
    double v[3];
    if (!cli_parse_double(CMD, opt, buf, -1e6, 1e6, &v[0]) || !cli_parse_double(CMD, opt, c1 + 1, -1e6, 1e6, &v[1]) ||
        !cli_parse_double(CMD, opt, c2 + 1, -1e6, 1e6, &v[2]))
        return 0;
    *out = soak_v3(v[0], v[1], v[2]);
    return 1;
}

static int parse_axis(const char *text, soak_vec3 *out)
{
    static const char *const names[] = {"x", "y", "z", "-x", "-y", "-z"};
    for (int k = 0; k < 6; ++k)
        if (!strcmp(text, names[k])) {
            double s = k < 3 ? 1.0 : -1.0;
            int a = k % 3;
            *out = soak_v3(a == 0 ? s : 0, a == 1 ? s : 0, a == 2 ? s : 0);
            return 1;
        }
    cli_error(CMD, "--up: expected x, y, z, -x, -y or -z, got '%s'", text);
    return 0;
}

static void on_progress(void *user, double fraction)
{
    cli_progress_update(user, fraction);
}

/* Writes every requested image or none: all are staged, then renamed
 * together, so a failure keeps every previous output. */
static int write_outputs(const char *const *paths, const soak_image *const *imgs, int n)
{
    char err[4352] = "";
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = SOAK_OK;
    for (int k = 0; k < n && st == SOAK_OK; ++k)
        if (paths[k]) st = soak_bake_stage(&stage, paths[k], imgs[k], 0, err, sizeof err);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return bake_fail(CMD, st, err);
    }
    st = soak_staged_commit(&stage, err, sizeof err);
    return st == SOAK_OK ? SOAK_EXIT_OK : bake_fail(CMD, st, err);
}

int soak_bake_rain_main(int argc, char **argv)
{
    soak_rain_params p;
    soak_rain_defaults(&p);
    p.up = soak_v3(0, 1, 0);
    int have_dir = 0;
    const char *mesh_path = NULL, *exposure_path = NULL, *water_path = NULL;
    bake_opts o;
    bake_opts_init(&o, CMD, 0, 0);
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v;
        long n;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return SOAK_EXIT_OK;
        }
        if (cli_is(a, "--frames") || cli_is(a, "--time") || cli_is(a, "--frame-time") || cli_is(a, "--frame-origin") ||
            cli_is(a, "--float")) {
            cli_error(CMD, "option %s does not apply to rain bakes", a);
            return SOAK_EXIT_USAGE;
        }
        int r = bake_opts_parse(&o, argc, argv, &i);
        if (r < 0) return SOAK_EXIT_USAGE;
        if (r > 0) continue;
#define NEED_VALUE                                                                                                     \
    if (!(v = cli_value(CMD, argc, argv, &i))) return SOAK_EXIT_USAGE
        if (cli_is(a, "--exposure")) {
            NEED_VALUE;
            exposure_path = v;
        } else if (cli_is(a, "--water")) {
            NEED_VALUE;
            water_path = v;
        } else if (cli_is(a, "--rays")) {
            NEED_VALUE;
            if (!cli_parse_int(CMD, "--rays", v, 1, 65536, &n)) return SOAK_EXIT_USAGE;
            p.rays = (int)n;
        } else if (cli_is(a, "--sky")) {
            NEED_VALUE;
            if (!strcmp(v, "rain")) p.sky = SOAK_RAIN_SKY_RAIN;
            else if (!strcmp(v, "hemisphere")) p.sky = SOAK_RAIN_SKY_HEMISPHERE;
            else {
                cli_error(CMD, "--sky: expected rain or hemisphere, got '%s'", v);
                return SOAK_EXIT_USAGE;
            }
        } else if (cli_is(a, "--up")) {
            NEED_VALUE;
            if (!parse_axis(v, &p.up)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--rain-dir")) {
            NEED_VALUE;
            if (!parse_vec("--rain-dir", v, &p.rain_dir)) return SOAK_EXIT_USAGE;
            have_dir = 1;
        } else if (cli_is(a, "--spread")) {
            NEED_VALUE;
            if (!cli_parse_double(CMD, "--spread", v, 0, 89, &p.spread_deg)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--duration")) {
            NEED_VALUE;
            if (!cli_parse_double(CMD, "--duration", v, 0, 1e7, &p.duration)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--steps")) {
            NEED_VALUE;
            if (!cli_parse_int(CMD, "--steps", v, 1, 100000, &n)) return SOAK_EXIT_USAGE;
            p.steps = (int)n;
        } else if (cli_is(a, "--rainfall")) {
            NEED_VALUE;
            if (!cli_parse_double(CMD, "--rainfall", v, 0, 1000, &p.rainfall_mm_h)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--drop-size")) {
            NEED_VALUE;
            if (!cli_parse_double(CMD, "--drop-size", v, 1e-6, 0.01, &p.drop_diameter)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--splat")) {
            NEED_VALUE;
            if (!cli_parse_double(CMD, "--splat", v, 0, 1, &p.splat_radius)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--evaporation")) {
            NEED_VALUE;
            if (!cli_parse_double(CMD, "--evaporation", v, 0, 1000, &p.evaporation_mm_h)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--retention")) {
            NEED_VALUE;
            if (!cli_parse_double(CMD, "--retention", v, 0, 0.1, &p.retention)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--saturation")) {
            NEED_VALUE;
            if (!cli_parse_double(CMD, "--saturation", v, 1e-9, 1, &p.saturation_depth)) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--flow-iterations")) {
            NEED_VALUE;
            if (!cli_parse_int(CMD, "--flow-iterations", v, 0, 100000, &n)) return SOAK_EXIT_USAGE;
            p.flow_iterations = (int)n;
        } else if (cli_is(a, "--gutter")) {
            NEED_VALUE;
            if (!cli_parse_int(CMD, "--gutter", v, 0, 64, &n)) return SOAK_EXIT_USAGE;
            p.gutter = (int)n;
        } else if (a[0] == '-' && a[1] != '\0') {
            cli_error(CMD, "unknown option '%s' (see --help)", a);
            return SOAK_EXIT_USAGE;
        } else if (!mesh_path) {
            mesh_path = a;
        } else {
            cli_error(CMD, "unexpected argument '%s' (one mesh only)", a);
            return SOAK_EXIT_USAGE;
        }
#undef NEED_VALUE
    }
    if (!mesh_path) {
        cli_error(CMD, "a MESH file is required (see --help)");
        return SOAK_EXIT_USAGE;
    }
    if (!have_dir) p.rain_dir = p.up;
    p.seed = o.seed;
    if (soak_v3_dot(p.rain_dir, p.up) <= 1e-6 * soak_v3_len(p.rain_dir)) {
        cli_error(CMD, "--rain-dir: the rain must come from above (positive component along --up)");
        return SOAK_EXIT_USAGE;
    }
    const char *inputs[1] = {mesh_path};
    const char *extra[2] = {exposure_path, water_path};
    int rc = bake_opts_check(&o, inputs, 1);
    if (rc) return rc;
    for (int k = 0; k < 2; ++k) {
        if (!extra[k]) continue;
        char err[4352];
        soak_status st = soak_bake_check_output(extra[k], inputs, 1, err, sizeof err);
        if (st != SOAK_OK) {
            cli_error(CMD, "%s: %s", k ? "--water" : "--exposure", err);
            return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
        }
        if (soak_path_same(extra[k], o.output) || (k == 1 && exposure_path && soak_path_same(extra[1], extra[0]))) {
            cli_error(CMD, "%s: same file as another output", k ? "--water" : "--exposure");
            return SOAK_EXIT_USAGE;
        }
    }

    char err[4352] = "";
    soak_mesh mesh;
    soak_status st = soak_mesh_load(mesh_path, 1, &mesh, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    cli_progress bar;
    cli_progress_start(&bar, CMD, 1.0);
    soak_bake_exec exec = {(int)o.threads, on_progress, &bar};
    soak_rain_result res;
    st = soak_bake_rain(&mesh, (int)o.width, (int)o.height, &p, &exec, &res, err, sizeof err);
    cli_progress_finish(&bar);
    soak_mesh_free(&mesh);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s: %s", mesh_path, err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    const char *paths[3] = {o.output, exposure_path, water_path};
    const soak_image *imgs[3] = {&res.wetness, &res.exposure, &res.water};
    rc = write_outputs(paths, imgs, 3);
    soak_rain_result_free(&res);
    if (rc == SOAK_EXIT_OK) printf("%s: %ldx%ld rain wetness from %s\n", o.output, o.width, o.height, mesh_path);
    return rc;
}
