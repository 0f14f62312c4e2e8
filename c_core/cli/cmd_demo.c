/* soak demo: the main job of README's first command. Writes into one
 * folder: the wet-vs-dry albedo table (printed and as CSV), a swatch sheet
 * of every preset from dry to wet, baked wet maps and a wet-vs-dry render of
 * the default scene. The bake and render steps run the same code as the
 * `soak bake` and `soak render` commands (their command lines are printed so
 * a user can rerun or vary them). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "soak/data_dir.h"
#include "soak/image.h"
#include "soak/io_guard.h"
#include "soak/preset.h"
#include "soak/scene.h"
#include "soak/staged.h"
#include "soak/wetness.h"

#define SWATCH 96
#define N_WET 5

typedef struct demo_args {
    const char *dir, *materials, *scene;
    int quick;
} demo_args;

#define F(field) CLI_FIELD(demo_args, field)
static const cli_opt demo_opts[] = {
    {"--out", NULL, CLI_OPT_STRING, F(dir), .meta = "DIR", .help = "output folder (default out/demo)"},
    {"--quick", NULL, CLI_OPT_FLAG, .flag = 1, F(quick), .help = "lower the render's samples (used by the tests)"},
    {"--materials", NULL, CLI_OPT_STRING, F(materials), .meta = "FILE",
     .help = "preset file (default: $SOAK_MATERIALS, else the shipped one)"},
    {"--scene", NULL, CLI_OPT_STRING, F(scene), .meta = "SCENE.json",
     .help = "scene to render (default scenes/default_wet_dry.json\nof the data folder: see soak --help)"},
};
#undef F

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak demo [--out DIR] [--quick] [--materials FILE] [--scene SCENE.json]\n\n"
            "Runs the main job on the bundled defaults and writes into DIR (default out/demo):\n"
            "  albedo_table.csv   dry and wet albedo of every preset (also printed)\n"
            "  swatches.png       each preset lit from the upper left at wetness 0, .25, .5, .75, 1\n"
            "  wetmap_*.exr/.png  baked wet maps (turbulence and border-first drying)\n"
            "  render_wet_dry.exr/.png  the default scene (scenes/default_wet_dry.json), 64 spp\n\n"
            "options:\n");
    const cli_opt_table tables[] = {CLI_TABLE(demo_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out, "\nexample:\n  soak demo --out out/demo\n");
}

static int make_dir(const char *cmd, const char *path)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; ++p)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0755) != 0 && errno != EEXIST) break;
            *p = '/';
        }
    if (mkdir(buf, 0755) != 0 && errno != EEXIST) {
        cli_error(cmd, "--out: cannot create folder '%s': %s", path, strerror(errno));
        return 0;
    }
    return 1;
}

/* A sphere lit by a distant light from the upper left plus a dim sky: the
 * diffuse part uses the preset's wet albedo; a film adds a sharp highlight
 * (Fresnel at normal incidence ~2 % scaled up for visibility is NOT used:
 * the highlight's weight is the film's own coverage, its size fixed). */
static void draw_swatch(soak_image *img, int x0, int y0, const soak_wet_params *w, int metal)
{
    const soak_vec3 light = soak_v3_norm(soak_v3(-0.5, 0.6, 0.62));
    for (int y = 0; y < SWATCH; ++y)
        for (int x = 0; x < SWATCH; ++x) {
            double u = (x + 0.5) / SWATCH * 2 - 1, v = 1 - (y + 0.5) / SWATCH * 2, r2 = u * u + v * v;
            float *px = img->pixels + ((size_t)(y0 + y) * img->width + (x0 + x)) * 3;
            if (r2 > 0.92 * 0.92) {
                px[0] = px[1] = px[2] = 0.18f;
                continue;
            }
            double s = 1 / 0.92;
            soak_vec3 n = soak_v3(u * s, v * s, sqrt(fmax(0, 1 - r2 * s * s)));
            double diff = fmax(0, soak_v3_dot(n, light)) * 0.85 + 0.15 * (0.5 + 0.5 * n.y);
            if (metal) {
                /* A metal shows its environment: mirror the view (+z) about n
                 * into a sky-over-ground gradient, tinted by its reflectance. */
                double ry = 2 * n.z * n.y;
                diff = ry > 0 ? 0.55 + 0.45 * ry : 0.12 + 0.1 * (1 + ry);
            }
            soak_vec3 h = soak_v3_norm(soak_v3_add(light, soak_v3(0, 0, 1)));
            double spec_w = w->film_coverage + w->water_specular_weight;
            double spec = spec_w * pow(fmax(0, soak_v3_dot(n, h)), 400) * 3.0;
            px[0] = (float)(w->albedo.r * diff + spec);
            px[1] = (float)(w->albedo.g * diff + spec);
            px[2] = (float)(w->albedo.b * diff + spec);
        }
}

/* The swatch row of preset i (wetness 0 .. 1) and its line of the table
 * and of the CSV. */
static int preset_row(const char *cmd, const soak_preset *p, const soak_liquid *water, int i, soak_image *sheet,
                      FILE *csv)
{
    soak_wet_params dry = {0}, wet = {0};
    for (int k = 0; k < N_WET; ++k) {
        soak_wet_input in = soak_wet_input_steady(p, k / (double)(N_WET - 1));
        soak_wet_params w;
        soak_status st = soak_wetness_eval(p, water, &in, &w);
        if (st != SOAK_OK) {
            cli_error(cmd, "preset '%s': wetness mapping failed: %s", p->name, soak_status_str(st));
            return 0;
        }
        if (k == 0) dry = w;
        if (k == N_WET - 1) wet = w;
        draw_swatch(sheet, k * SWATCH, i * SWATCH, &w, p->kind == SOAK_KIND_CONDUCTOR);
    }
    /* Diffuse albedo (what darkens) and the film's specular share of the
     * total hemispherical reflectance (what makes wet surfaces glossy). */
    double ld = soak_rgb_luminance(dry.albedo);
    double lw = soak_rgb_luminance(wet.albedo);
    double spec = soak_rgb_luminance(soak_rgb3(wet.albedo_total.r - wet.albedo.r, wet.albedo_total.g - wet.albedo.g,
                                               wet.albedo_total.b - wet.albedo.b));
    double ratio = ld > 0 ? lw / ld : 1.0;
    printf("%-12s %-21s (%.3f, %.3f, %.3f)   (%.3f, %.3f, %.3f)   %7.2f   %9.3f\n", p->name,
           soak_material_kind_name(p->kind), dry.albedo.r, dry.albedo.g, dry.albedo.b, wet.albedo.r, wet.albedo.g,
           wet.albedo.b, ratio, spec);
    fprintf(csv, "%s,%s,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", p->name, soak_material_kind_name(p->kind),
            dry.albedo.r, dry.albedo.g, dry.albedo.b, wet.albedo.r, wet.albedo.g, wet.albedo.b, ratio, spec);
    return 1;
}

/* Every preset's row into the open CSV and the sheet. */
static int fill_table(const char *cmd, const soak_preset_db *db, soak_image *sheet, FILE *csv)
{
    const soak_liquid *water = soak_presets_find_liquid(db, "water");
    fprintf(csv, "material,kind,dry_r,dry_g,dry_b,wet_r,wet_g,wet_b,wet_over_dry,film_specular\n");
    printf("%-12s %-21s %-23s %-23s %-7s %s\n", "material", "kind", "dry albedo (RGB)", "wet albedo (w=1)", "wet/dry",
           "film spec");
    for (int i = 0; i < soak_presets_count(db); ++i)
        if (!preset_row(cmd, soak_presets_at(db, i), water, i, sheet, csv)) return 0;
    return 1;
}

/* The table and the swatch sheet are replaced together (soak/staged.h):
 * both are staged, then committed, or neither is. */
static int write_table_and_swatches(const char *cmd, const soak_preset_db *db, const char *dir)
{
    char path[4096], sheet_path[4096], err[4352] = "";
    snprintf(path, sizeof path, "%s/albedo_table.csv", dir);
    snprintf(sheet_path, sizeof sheet_path, "%s/swatches.png", dir);
    soak_staged stage;
    soak_staged_init(&stage);
    FILE *csv = NULL;
    soak_image sheet = {0};
    soak_status st = soak_staged_open(&stage, path, &csv, err, sizeof err);
    int ok = st == SOAK_OK;
    if (ok && soak_image_alloc(&sheet, SWATCH * N_WET, SWATCH * soak_presets_count(db), 3) != SOAK_OK) {
        fclose(csv);
        csv = NULL;
        snprintf(err, sizeof err, "out of memory for the swatch sheet");
        ok = 0;
    }
    int rows = ok && fill_table(cmd, db, &sheet, csv);
    if (csv) st = soak_staged_close(csv, path, err, sizeof err);
    soak_image_write_opts opts = {SOAK_TONE_SRGB, SOAK_PIXEL_UINT8};
    if (rows && st == SOAK_OK) st = soak_image_stage(&stage, sheet_path, &sheet, &opts, err, sizeof err);
    soak_image_free(&sheet);
    if (rows && st == SOAK_OK) st = soak_staged_commit(&stage, err, sizeof err);
    else soak_staged_abort(&stage);
    if (!rows || st != SOAK_OK) {
        if (!ok || (rows && st != SOAK_OK)) cli_error(cmd, "%s", err);
        return 0;
    }
    printf("(diffuse albedo under diffuse light; wet = fully wet with a water film; wet/dry = luminance ratio;\n"
           " film spec = hemispherical specular reflectance the film adds)\n");
    printf("wrote %s/albedo_table.csv and %s (rows: presets in table order; columns: wetness 0 .. 1)\n", dir,
           sheet_path);
    return 1;
}

/* Runs another subcommand in-process, printing its command line first. */
static int run_step(const char *cmd, int (*fn)(int, char **), int argc, char **argv)
{
    printf("\n$ soak");
    for (int i = 0; i < argc; ++i) printf(" %s", argv[i]);
    printf("\n");
    fflush(stdout);
    int rc = fn(argc, argv);
    if (rc != SOAK_EXIT_OK) cli_error(cmd, "step 'soak %s' failed (exit %d)", argv[0], rc);
    return rc == SOAK_EXIT_OK;
}

/* [JLD99]'s procedural wetness (thresholded turbulence), the same pattern
 * drying border-first ([Hnat06]) half-way, and a beach with four waves. */
static int bake_maps(const char *cmd, const char *dir)
{
    char turb_exr[4096], turb_png[4096], dry_png[4096], waves_png[4096];
    snprintf(turb_exr, sizeof turb_exr, "%s/wetmap_turbulence.exr", dir);
    snprintf(turb_png, sizeof turb_png, "%s/wetmap_turbulence.png", dir);
    snprintf(dry_png, sizeof dry_png, "%s/wetmap_drying_t0.3.png", dir);
    snprintf(waves_png, sizeof waves_png, "%s/wetmap_waves.png", dir);
    printf("\n== baked wet maps (linear; PNGs are 16-bit with gAMA 1.0)\n");
    char *turb[] = {"bake", "turbulence", "--turbulence", "--octaves", "6", "--frequency", "6", "--threshold", "0.3",
                    "--softness", "0.08", "--tileable", "--width", "512", "--height", "512", "--seed", "7", "-o",
                    turb_exr};
    char *turb2[] = {"bake", "turbulence", "--turbulence", "--octaves", "6", "--frequency", "6", "--threshold", "0.3",
                     "--softness", "0.08", "--tileable", "--width", "512", "--height", "512", "--seed", "7", "-o",
                     turb_png};
    char *dry[] = {"bake", "drying", turb_exr, "--t-fill", "0.2", "--noise", "0.3", "--time", "0.3", "-o", dry_png};
    char *waves[] = {"bake", "waves", "--waves", "4", "--width", "1024", "--height", "512", "--seed", "3", "-o",
                     waves_png};
    return run_step(cmd, soak_cmd_bake, (int)(sizeof turb / sizeof *turb), turb) &&
           run_step(cmd, soak_cmd_bake, (int)(sizeof turb2 / sizeof *turb2), turb2) &&
           run_step(cmd, soak_cmd_bake, (int)(sizeof dry / sizeof *dry), dry) &&
           run_step(cmd, soak_cmd_bake, (int)(sizeof waves / sizeof *waves), waves);
}

/* Wet (left) vs dry (right) sandstone spheres on half-wet sand under a sun. */
static int render_scene(const char *cmd, const char *dir, const char *scene, int quick)
{
    char png[4096], exr[4096];
    snprintf(png, sizeof png, "%s/render_wet_dry.png", dir);
    snprintf(exr, sizeof exr, "%s/render_wet_dry.exr", dir);
    printf("\n== wet vs dry render (left sphere and left half of the ground wet)\n");
    char *spp = quick ? "4" : "64";
    char *to_exr[] = {"render", (char *)scene, "-o", exr, "--spp", spp, "--seed", "1"};
    if (!run_step(cmd, soak_cmd_render, (int)(sizeof to_exr / sizeof *to_exr), to_exr)) return 0;
    /* Same seed, same pixels: the PNG is the EXR tone-mapped with the
     * scene's own exposure (see soak render --help). */
    char *to_png[] = {"render", (char *)scene, "-o", png, "--spp", spp, "--seed", "1", "--quiet"};
    if (!run_step(cmd, soak_cmd_render, (int)(sizeof to_png / sizeof *to_png), to_png)) return 0;
    printf("wrote %s (linear) and %s (sRGB)\n", exr, png);
    return 1;
}

/* Everything the demo reads is checked before it writes anything: the
 * output folder, the presets, the scene (loaded once to validate it and list
 * its files) and that no output is one of those inputs. */
static int check_before_writing(const char *cmd, const char *dir, const char *materials, const char *scene_path)
{
    struct stat sb;
    if (stat(dir, &sb) == 0 && !S_ISDIR(sb.st_mode)) {
        cli_error(cmd, "--out '%s': is a file, not a folder", dir);
        return SOAK_EXIT_USAGE;
    }
    static const char *const outputs[] = {"albedo_table.csv",      "swatches.png",       "wetmap_turbulence.exr",
                                          "wetmap_turbulence.png", "wetmap_drying_t0.3.png", "wetmap_waves.png",
                                          "render_wet_dry.exr",    "render_wet_dry.png"};
    char err[4352] = "";
    soak_scene scene;
    soak_status st = soak_scene_load(scene_path, &scene, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(cmd, "--scene: %s", err);
        return SOAK_EXIT_FAIL;
    }
    soak_io_guard g;
    soak_io_guard_init(&g);
    st = soak_io_guard_input(&g, "--materials", materials);
    if (st == SOAK_OK) st = soak_io_guard_input(&g, "--scene", scene_path);
    for (int i = 0; i < scene.n_inputs && st == SOAK_OK; ++i)
        st = soak_io_guard_input(&g, "file of the scene", scene.inputs[i]);
    soak_scene_free(&scene);
    for (size_t i = 0; i < sizeof outputs / sizeof *outputs && st == SOAK_OK; ++i) {
        char path[4352];
        snprintf(path, sizeof path, "%s/%s", dir, outputs[i]);
        st = soak_io_guard_output(&g, "output", path);
    }
    if (st == SOAK_OK) st = soak_io_guard_check(&g, err, sizeof err);
    soak_io_guard_free(&g);
    if (st != SOAK_OK) {
        cli_error(cmd, "--out: %s", st == SOAK_ERR_ARG ? err : soak_status_str(st));
        return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    }
    return 0;
}

/* The presets and the scene of the data folder (soak/data_dir.h) unless
 * given: n bytes each in materials and scene. */
static int find_defaults(const char *cmd, demo_args *a, char *materials, char *scene, size_t n)
{
    char err[4352];
    if (!a->materials) {
        if (soak_presets_default_path(materials, n, err, sizeof err) != SOAK_OK) {
            cli_error(cmd, "%s", err);
            return 0;
        }
        a->materials = materials;
    }
    if (!a->scene) {
        if (soak_data_path("scenes/default_wet_dry.json", scene, n, err, sizeof err) != SOAK_OK) {
            cli_error(cmd, "%s", err);
            return 0;
        }
        a->scene = scene;
    }
    return 1;
}

int soak_cmd_demo(int argc, char **argv)
{
    const char *cmd = "demo";
    demo_args a = {.dir = "out/demo"};
    const cli_spec spec = {cmd, "option", "'soak demo --help'", usage, NULL, NULL};
    const cli_opt_table tables[] = {CLI_TABLE(demo_opts, &a)};
    int rc = cli_opts_parse(&spec, tables, 1, argc, argv);
    if (rc >= 0) return rc;
    char materials[SOAK_PRESETS_PATH_MAX], scene[SOAK_PRESETS_PATH_MAX];
    if (!find_defaults(cmd, &a, materials, scene, sizeof materials)) return SOAK_EXIT_FAIL;
    soak_preset_db *db = NULL;
    char err[2048] = "";
    if (soak_presets_load(a.materials, &db, err, sizeof err) != SOAK_OK) {
        cli_error(cmd, "%s", err);
        return SOAK_EXIT_FAIL;
    }
    rc = check_before_writing(cmd, a.dir, a.materials, a.scene);
    if (rc || !make_dir(cmd, a.dir)) {
        soak_presets_free(db);
        return rc ? rc : SOAK_EXIT_FAIL;
    }
    printf("== wet vs dry albedo of every preset (%s)\n", a.materials);
    int ok = write_table_and_swatches(cmd, db, a.dir);
    soak_presets_free(db);
    if (!ok || !bake_maps(cmd, a.dir) || !render_scene(cmd, a.dir, a.scene, a.quick)) return SOAK_EXIT_FAIL;
    printf("\ndemo finished: open %s/\n", a.dir);
    return SOAK_EXIT_OK;
}
