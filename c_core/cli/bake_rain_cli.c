/* soak bake rain: rain wetting of a mesh baked into its UV texture (model in
 * soak/bake_rain.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_budget.h"
#include "bake_cli.h"
#include "bake_uv_cli.h"
#include "cli.h"
#include "soak/bake_rain.h"
#include "soak/geometry.h"
#include "soak/preset.h"
#include "soak/staged.h"

#define CMD "bake rain"

typedef struct rain_args {
    soak_rain_params p;
    int have_dir, up_axis, no_film, have_fps, have_time, have_frame_time, have_angle;
    const char *preset, *materials; /* --preset: the contact angle of a preset */
    double fps;
    const char *mesh_path, *exposure_path, *water_path, *film_path, *vertex_path, *pov_name;
    int float_exr;                /* the sequence table's --float, for the extra maps */
    soak_rain_frames *frames;     /* --frames: the sequence's state */
    soak_rain_frame last;         /* the last frame's balance */
    bake_uv_opts uvo;             /* --uv-set, --uv-outside, --strict */
} rain_args;

#define RAIN_MAX_FPS 10000

/* Rain direction components: any finite vector (normalised by the bake). */
#define RAIN_MAX_COMPONENT 1e6
/* --drop-size's floor: the library takes any diameter > 0. */
#define RAIN_MIN_DROP 1e-6
/* --saturation's floor: the library takes any depth > 0. */
#define RAIN_MIN_SATURATION 1e-9

static int read_rain_dir(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    rain_args *a = dst;
    char buf[256];
    snprintf(buf, sizeof buf, "%s", text);
    char *c1 = strchr(buf, ','), *c2 = c1 ? strchr(c1 + 1, ',') : NULL;
    if (!c1 || !c2 || strchr(c2 + 1, ',')) {
        cli_error(cmd, "%s: expected X,Y,Z, got '%s'", o->name, text);
        return 0;
    }
    *c1 = *c2 = '\0';
    double v[3];
    if (!cli_parse_double(cmd, o->name, buf, o->lo, o->hi, &v[0]) ||
        !cli_parse_double(cmd, o->name, c1 + 1, o->lo, o->hi, &v[1]) ||
        !cli_parse_double(cmd, o->name, c2 + 1, o->lo, o->hi, &v[2]))
        return 0;
    a->p.rain_dir = soak_v3(v[0], v[1], v[2]);
    return 1;
}

static const cli_choice skies[] = {{"rain", SOAK_RAIN_SKY_RAIN, 0}, {"hemisphere", SOAK_RAIN_SKY_HEMISPHERE, 0},
                                   {NULL, 0, 0}};
/* Axis k of x, y, z, then -x, -y, -z. */
static const cli_choice axes[] = {{"x", 0, 0},  {"y", 1, 0},  {"z", 2, 0}, {"-x", 3, 0},
                                  {"-y", 4, 0}, {"-z", 5, 0}, {NULL, 0, 0}};

#define F(field) CLI_FIELD(rain_args, field)
static const cli_opt rain_opts[] = {
    {"--per-vertex", NULL, CLI_OPT_STRING, F(vertex_path), .meta = "PATH",
     .help = "wetness per vertex instead of a map: .ply (grey vertex colours), .csv,\n"
             ".gltf/.glb (COLOR_0 = linear wetness grey, float attribute _WETNESS), .inc\n"
             "(a POV-Ray mesh2 with a Soak_Mesh_Texture per vertex: povray/soak_mesh.inc);\n"
             "for meshes with or without UVs; each face baked as its own chart, so water\n"
             "does not flow from face to face (films on slopes under-estimated; exposure\n"
             "right); -o, --exposure, --water, --film, --frames not taken"},
    {"--pov-name", NULL, CLI_OPT_STRING, F(pov_name), .meta = "NAME",
     .help = "--per-vertex OUT.inc: the mesh2's identifier (default Soak_Wet_Mesh)"},
    {"--exposure", NULL, CLI_OPT_STRING, F(exposure_path), .meta = "PATH",
     .help = "also write the sky exposure (1 = open horizontal surface)"},
    {"--water", NULL, CLI_OPT_STRING, F(water_path), .meta = "PATH",
     .help = "also write the water depth (m; with --frames a pattern)"},
    {"--film", NULL, CLI_OPT_STRING, F(film_path), .meta = "PATH",
     .help = "also write the falling film thickness while rain falls (m; use .exr;\nwith --frames a pattern: the film of each frame)"},
    {"--no-film", NULL, CLI_OPT_FLAG, .flag = 1, F(no_film),
     .help = "no falling film: slopes keep only the flat film times n.up (walls drain)"},
    {"--preset", NULL, CLI_OPT_STRING, F(preset), .meta = "NAME",
     .help = "take --contact-angle from this preset (soak materials; wetting.contact_angle_deg,\n"
             "above 90 taken as 90: such surfaces bead, see soak bake beads)"},
    {"--materials", NULL, CLI_OPT_STRING, F(materials), .meta = "PATH",
     .help = "presets file for --preset (default: $SOAK_MATERIALS or the shipped one)"},
    {"--contact-angle", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 90, F(p.contact_angle_deg),
     CLI_SEEN(rain_args, have_angle), .meta = "DEG",
     .help = "the surface's contact angle with water, %R deg: a film thinner than\n"
             "Hartley & Murgatroyd's (1964) minimum wetting rate breaks into runnels,\n"
             "placed on the surface's grooves (else by --seed); with --frames each frame's\n"
             "film gathers into the same runnels (default 0: the film holds)"},
    {"--rays", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_RAIN_MAX_RAYS, F(p.rays), .meta = "N",
     .help = "rays per texel, %R (default 64)"},
    {"--sky", NULL, CLI_OPT_CHOICE, .choices = skies, F(p.sky), .meta = "rain|hemisphere",
     .help = "rain cone (default) or cosine hemisphere (ambient occlusion)"},
    {"--up", NULL, CLI_OPT_CHOICE, .choices = axes, F(up_axis), .meta = "x|y|z|-x|-y|-z",
     .help = "world up axis (default y, the OBJ/glTF convention)"},
    {"--rain-dir", NULL, CLI_OPT_CUSTOM, .parse = read_rain_dir, .lo = -RAIN_MAX_COMPONENT, .hi = RAIN_MAX_COMPONENT,
     CLI_SEEN(rain_args, have_dir), .meta = "X,Y,Z", .help = "direction the rain comes from (default: up)"},
    {"--spread", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_RAIN_MAX_SPREAD, F(p.spread_deg), .meta = "DEG",
     .help = "rain cone half-angle, %R (default 10)"},
    {"--duration", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_RAIN_MAX_DURATION, F(p.duration), .meta = "S",
     .help = "seconds of rain, 0 = exposure only (default 600)"},
    {"--steps", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_RAIN_MAX_STEPS, F(p.steps), .meta = "N",
     .help = "time steps, %R (default 32)"},
    {"--rainfall", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_RAIN_MAX_RATE, F(p.rainfall_mm_h), .meta = "MM_H",
     .help = "rainfall, %R mm/h (default 10)"},
    {"--drop-size", NULL, CLI_OPT_DOUBLE, .lo = RAIN_MIN_DROP, .hi = SOAK_RAIN_MAX_DROP, F(p.drop_diameter),
     .meta = "M", .help = "drop diameter, m (default 0.002)"},
    {"--splat", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_RAIN_MAX_SPLAT, F(p.splat_radius), .meta = "M",
     .help = "splat kernel standard deviation, m (default 0.002)"},
    {"--evaporation", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_RAIN_MAX_RATE, F(p.evaporation_mm_h), .meta = "MM_H",
     .help = "evaporation, %R mm/h (default 0.5)"},
    {"--retention", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_RAIN_MAX_RETENTION, F(p.retention), .meta = "M",
     .help = "film kept on a flat surface, m (default 0.0002)"},
    {"--saturation", NULL, CLI_OPT_DOUBLE, .lo = RAIN_MIN_SATURATION, .hi = SOAK_RAIN_MAX_SATURATION,
     F(p.saturation_depth), .meta = "M", .help = "depth giving wetness 1 - 1/e, m (default 0.0002)"},
    {"--flow-iterations", NULL, CLI_OPT_INT, .ilo = 0, .ihi = SOAK_RAIN_MAX_STEPS, F(p.flow_iterations), .meta = "N",
     .help = "routing sweeps per step, %R (default 16)"},
    {"--gutter", NULL, CLI_OPT_INT, .ilo = 0, .ihi = SOAK_RAIN_MAX_GUTTER, F(p.gutter), .meta = "N",
     .help = "texels of padding around UV islands, %R (default 4)"},
    {"--fps", NULL, CLI_OPT_DOUBLE, .lo = 1e-6, .hi = RAIN_MAX_FPS, F(fps), CLI_SEEN(rain_args, have_fps), .meta = "N",
     .help = "--frames: frames per second, frame f at t = f / N (default 24)"},
};
#undef F

#define RAIN_TABLES(o, a, u) {BAKE_IMAGE_TABLE(o), CLI_TABLE(rain_opts, (a)), BAKE_UV_TABLE(u), BAKE_SEQUENCE_TABLE(o)}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake rain MESH -o OUT [options]\n"
            "       soak bake rain MESH --frames A-B -o wet.%%04d.exr [options]\n"
            "       soak bake rain MESH --per-vertex wet.ply|.csv|.gltf|.glb|.inc [options]\n\n"
            "Rain wet map of a mesh (FBX, glTF, OBJ, ... listed below) in its UVs, or with\n"
            "--per-vertex one wetness per vertex (meshes without UVs too), at a texture\n"
            "resolution: per-texel sky exposure by ray casting through the mesh (Embree), drop\n"
            "impacts as a Poisson process with a splat kernel, evaporation, and downhill flow\n"
            "that fills concave upward-facing regions (puddles); inclined, vertical and\n"
            "overhanging faces keep the laminar film (Nusselt 1916) of the water running over\n"
            "them, thicker where the flow collects (streaks), dripping off at overhangs.\n"
            "Lengths in the mesh unit (metres), times in seconds. Same seed, same bytes, on\n"
            "any number of threads.\n"
            "-o is the wetness map, w = 1 - exp(-depth/saturation), and w = 1 where a film\n"
            "runs (thicker than 1 um): the film is supplied all the time, so the pores under it\n"
            "are full and it covers the surface.\n\n"
            "--frames A-B -o wet.%%04d.exr: a frame sequence over the rain and after it; frame f\n"
            "is at t = f / fps (--fps, default 24; or --time/--frame-time/--frame-origin as in\n"
            "every sequence bake), whatever range is baked, so chunks equal one run. The rain\n"
            "(mean rate, no drops: see `soak bake drops`) falls during [0, --duration]; the\n"
            "film runs down the faces as Nusselt's film in time (a kinematic wave, Lighthill &\n"
            "Whitham 1955): a face fills from the top, its front moving at 2 u_s under rain\n"
            "and at (2/3) u_s onto a dry face; after the rain it drains (Jeffreys 1930:\n"
            "h -> sqrt(nu x / (g sin theta t))) and evaporation dries what is left. --film and\n"
            "--water are then frame patterns too; --exposure is one map. Time steps are\n"
            "--duration / --steps, the same after the rain. Prints where the water went by\n"
            "the last frame.\n"
            "The single map (no --frames) is not a frame of the sequence: it holds the steady\n"
            "film of rain that has fallen long enough (kept on every face steeper than flat)\n"
            "and the water of --steps steps, at the rain's end. The sequence's film grows from\n"
            "the top of each face at its own speed and drains once the rain stops, so a frame\n"
            "at or after --duration can show less film and lower wetness (docs/rain.md).\n\n"
            "options:\n");
    cli_opt seq[BAKE_SHARED_OPTS_MAX];
    size_t n = bake_table_help(bake_sequence_opts, bake_sequence_opts_n, seq, "--frame-origin", BAKE_ORIGIN_ZERO_HELP);
    const cli_opt_table tables[] = {BAKE_IMAGE_TABLE(NULL), CLI_TABLE(rain_opts, NULL), BAKE_UV_TABLE(NULL), {seq, n, NULL}};
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    bake_uv_formats_help(out);
    fprintf(out, "\nexample:\n"
                 "  soak bake rain statue.glb --width 2048 --height 2048 --rays 64 --duration 1800 \\\n"
                 "       --exposure exposure.exr -o rain_wet.exr\n"
                 "  soak bake rain character.fbx --uv-set UVMap --strict -o wet.<UDIM>.exr\n"
                 "  soak bake rain wall.obj --up z --duration 600 --steps 60 --fps 0.04 --frames 0-23 \\\n"
                 "       --film film.%%04d.exr -o wet.%%04d.exr\n"
                 "  soak bake rain part.stl --up z --width 1024 --height 1024 --per-vertex wet.ply\n"
                 "  soak bake rain scan.glb --width 1024 --height 1024 --per-vertex wet.glb\n"
                 "  soak bake rain rock.obj --per-vertex rock_wet.inc --pov-name Rock_Wet\n");
}

static int mesh_arg(void *ctx, const char *arg)
{
    rain_args *a = ctx;
    if (a->mesh_path) {
        cli_error(CMD, "unexpected argument '%s' (one mesh only)", arg);
        return 0;
    }
    a->mesh_path = arg;
    return 1;
}

static void on_progress(void *user, double fraction)
{
    cli_progress_update(user, fraction);
}

/* Writes every requested image or none: all are staged, then renamed
 * together, so a failure keeps every previous output. */
static int write_outputs(const char *const *paths, const soak_image *const *imgs, int n, int float_exr)
{
    char err[4352] = "";
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = SOAK_OK;
    for (int k = 0; k < n && st == SOAK_OK; ++k)
        if (paths[k]) st = soak_bake_stage(&stage, paths[k], imgs[k], float_exr, err, sizeof err);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return bake_fail(CMD, st, err);
    }
    st = soak_staged_commit(&stage, err, sizeof err);
    return st == SOAK_OK ? SOAK_EXIT_OK : bake_fail(CMD, st, err);
}

/* The sequence options: frame f at --time + (f - origin) / fps, origin 0
 * unless given, as `soak bake drops`. Returns -1 to go on, else the exit
 * code. */
static int settle_frames(rain_args *a, bake_opts *o)
{
    if (!o->have_frames && (a->have_fps || !isnan(o->time))) {
        cli_error(CMD, "%s needs an image sequence: give --frames A-B", a->have_fps ? "--fps" : "--time");
        return SOAK_EXIT_USAGE;
    }
    if (!o->have_frames) return -1;
    if (a->have_fps) o->frame_time = 1.0 / a->fps;
    if (isnan(o->time)) o->time = 0;
    if (!o->have_origin) o->origin = 0, o->have_origin = 1;
    if (!(a->p.duration > 0)) {
        cli_error(CMD, "--frames needs rain: --duration must be > 0");
        return SOAK_EXIT_USAGE;
    }
    return -1;
}

/* --preset: its contact angle unless --contact-angle is given. Returns -1
 * to go on, else the exit code. */
static int angle_from_preset(rain_args *a)
{
    if (!a->preset) return -1;
    char err[4352] = "";
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(a->materials, &db, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "--preset: %s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    const soak_preset *p = soak_presets_find(db, a->preset);
    int rc = -1;
    if (!p) {
        cli_error(CMD, "--preset: no preset named '%s' in %s (see soak materials)", a->preset, soak_presets_path(db));
        rc = SOAK_EXIT_USAGE;
    } else if (!(p->contact_angle_deg >= 0)) {
        cli_error(CMD, "--preset %s: %s gives no wetting.contact_angle_deg; give --contact-angle", a->preset,
                  soak_presets_path(db));
        rc = SOAK_EXIT_USAGE;
    } else if (!a->have_angle) {
        a->p.contact_angle_deg = p->contact_angle_deg < 90.0 ? p->contact_angle_deg : 90.0;
    }
    soak_presets_free(db);
    return rc;
}

/* Returns -1 to go on, else the exit code. */
static int parse_args(int argc, char **argv, rain_args *a, bake_opts *o)
{
    memset(a, 0, sizeof *a);
    soak_rain_defaults(&a->p);
    a->up_axis = 1;
    bake_opts_init(o, CMD, NAN, 1.0 / 24);
    const cli_spec spec = BAKE_SPEC(CMD, usage, mesh_arg, a);
    bake_uv_opts_init(&a->uvo);
    const cli_opt_table tables[] = RAIN_TABLES(o, a, &a->uvo);
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    if (rc >= 0) return rc;
    if (!a->mesh_path) {
        cli_error(CMD, "a MESH file is required (see --help)");
        return SOAK_EXIT_USAGE;
    }
    if (a->materials && !a->preset) {
        cli_error(CMD, "--materials is the presets file for --preset: give --preset NAME too");
        return SOAK_EXIT_USAGE;
    }
    if ((rc = angle_from_preset(a)) >= 0) return rc;
    double s = a->up_axis < 3 ? 1.0 : -1.0;
    int k = a->up_axis % 3;
    a->p.up = soak_v3(k == 0 ? s : 0, k == 1 ? s : 0, k == 2 ? s : 0);
    if (!a->have_dir) a->p.rain_dir = a->p.up;
    a->p.seed = o->seed;
    a->p.film = !a->no_film;
    if (!(soak_v3_len(a->p.rain_dir) > 1e-12 && soak_v3_len(a->p.rain_dir) < 1e300)) {
        cli_error(CMD, "--rain-dir: a direction of length %g cannot be normalised (give e.g. 0,1,0)",
                  soak_v3_len(a->p.rain_dir));
        return SOAK_EXIT_USAGE;
    }
    a->p.uv.outside = (soak_uv_outside)a->uvo.outside;
    if (soak_v3_dot(a->p.rain_dir, a->p.up) <= 1e-6 * soak_v3_len(a->p.rain_dir)) {
        cli_error(CMD, "--rain-dir: the rain must come from above (positive component along --up)");
        return SOAK_EXIT_USAGE;
    }
    return settle_frames(a, o);
}

/* A sequence output of --frames besides -o: a pattern whose frames are
 * writable, not an input, not -o's. Returns 0 or the exit code. */
static int check_pattern(const bake_opts *o, const char *name, const char *pattern, const char *const *inputs)
{
    bake_opts other = *o;
    other.output = pattern;
    other.output_option = name;
    if (soak_bake_pattern_kind(pattern) != 1) {
        cli_error(CMD, "%s '%s': with --frames give a frame pattern such as film.%%04d.exr", name, pattern);
        return SOAK_EXIT_USAGE;
    }
    return bake_opts_check(&other, inputs, 1);
}

/* -o, --exposure and --water: writable, not the mesh, not each other.
 * Returns 0 or the exit code. */
static int check_outputs(const rain_args *a, const bake_opts *o)
{
    const char *inputs[1] = {a->mesh_path};
    const char *extra[3] = {a->exposure_path, a->water_path, a->film_path};
    bake_opts planned = *o;
    planned.plan_later = 1; /* below, all four outputs at once */
    o = &planned;
    static const char *const names[3] = {"--exposure", "--water", "--film"};
    int rc = bake_opts_check(o, inputs, 1);
    for (int k = 0; k < 3 && !rc; ++k) {
        if (!extra[k]) continue;
        if (o->have_frames && k > 0) { /* --water, --film: sequences like -o */
            if ((rc = check_pattern(o, names[k], extra[k], inputs)) != 0) return rc;
            continue;
        }
        char err[4352];
        soak_status st = soak_bake_check_output(extra[k], inputs, 1, err, sizeof err);
        if (st != SOAK_OK) {
            cli_error(CMD, "%s: %s", names[k], err);
            return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
        }
    }
    const bake_output outs[4] = {{"-o", o->output}, {names[0], extra[0]}, {names[1], extra[1]}, {names[2], extra[2]}};
    const bake_output mesh[1] = {{"MESH", a->mesh_path}};
    return rc ? rc : bake_plan_check(o, outs, 4, mesh, 1);
}

/* The way on for a mesh without UVs. */
static const char *no_uv_hint(const char *err)
{
    return strstr(err, "mesh has no UVs") ? " (--per-vertex OUT.ply bakes one wetness per vertex without them)" : "";
}

/* Loads the mesh and bakes it into res. */
static soak_status bake(const rain_args *a, const bake_opts *o, soak_rain_result *res)
{
    char err[4352] = "";
    soak_mesh mesh;
    soak_status st = soak_mesh_load_uv(a->mesh_path, &a->uvo.uv, &mesh, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s%s", err[0] ? err : soak_status_str(st), no_uv_hint(err));
        return st;
    }
    cli_progress bar;
    cli_progress_start(&bar, CMD, 1.0);
    soak_bake_exec exec = {(int)o->threads, on_progress, &bar};
    st = soak_bake_rain(&mesh, (int)o->width, (int)o->height, &a->p, &exec, res, err, sizeof err);
    cli_progress_finish(&bar);
    soak_mesh_free(&mesh);
    if (st != SOAK_OK) cli_error(CMD, "%s: %s", a->mesh_path, err[0] ? err : soak_status_str(st));
    return st;
}

/* One frame of --frames: -o's wetness into out, --film and --water
 * written here. */
static soak_status rain_frame(void *ctx, int frame, double time, const soak_bake_exec *exec, soak_image *out,
                              struct soak_staged *extra, char *err, size_t errlen)
{
    rain_args *a = ctx;
    soak_rain_frame fr;
    soak_status st = soak_rain_frames_at(a->frames, time, exec, &fr, err, errlen);
    if (st != SOAK_OK) {
        char why[4352];
        snprintf(why, sizeof why, "frame %d at %g s: %s", frame, time, err[0] ? err : soak_status_str(st));
        snprintf(err, errlen, "%s", why);
        return st;
    }
    const char *patterns[2] = {a->film_path, a->water_path};
    const soak_image *imgs[2] = {&fr.film, &fr.water};
    for (int k = 0; k < 2 && st == SOAK_OK; ++k) {
        char path[4096];
        if (!patterns[k]) continue;
        st = soak_bake_frame_path(patterns[k], frame, path, sizeof path);
        if (st == SOAK_OK) st = soak_bake_stage(extra, path, imgs[k], a->float_exr, err, errlen);
    }
    a->last.balance = fr.balance;
    *out = fr.wetness;
    fr.wetness.pixels = NULL;
    soak_rain_frame_free(&fr);
    return st;
}

/* --frames: the sequence, then --exposure, then where the water went. */
static int run_frames(rain_args *a, const bake_opts *o)
{
    char err[4352] = "";
    soak_mesh mesh;
    soak_status st = soak_mesh_load_uv(a->mesh_path, &a->uvo.uv, &mesh, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s%s", err[0] ? err : soak_status_str(st), no_uv_hint(err));
        return SOAK_EXIT_FAIL;
    }
    cli_progress bar;
    cli_progress_start(&bar, CMD " (exposure)", 1.0);
    soak_bake_exec exec = {(int)o->threads, on_progress, &bar};
    st = soak_rain_frames_create(&mesh, (int)o->width, (int)o->height, &a->p, &exec, &a->frames, err, sizeof err);
    cli_progress_finish(&bar);
    soak_mesh_free(&mesh);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s: %s", a->mesh_path, err[0] ? err : soak_status_str(st));
        return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    }
    a->float_exr = o->float_exr;
    int rc = bake_uv_verdict(CMD, a->mesh_path, soak_rain_frames_uv(a->frames), &a->uvo) ? SOAK_EXIT_FAIL
                                                                                        : bake_run_staged(o, rain_frame, a);
    if (rc == SOAK_EXIT_OK && a->exposure_path) {
        const char *paths[1] = {a->exposure_path};
        const soak_image *imgs[1] = {soak_rain_frames_exposure(a->frames)};
        rc = write_outputs(paths, imgs, 1, o->float_exr);
    }
    const soak_rain_balance *b = &a->last.balance;
    if (rc == SOAK_EXIT_OK)
        printf("%s: frames %ld-%ld, %ldx%ld, from %s\n", o->output, o->first, o->last, o->width, o->height,
               a->mesh_path);
    if (rc == SOAK_EXIT_OK) bake_uv_report(o->output, soak_rain_frames_uv(a->frames));
    if (rc == SOAK_EXIT_OK && b->in > 0.0)
        printf("by frame %ld (t = %g s) %.4g L fell on the mesh: %.1f %% dripped off, %.1f %% is on it, "
               "%.1f %% evaporated\n",
               o->last, bake_frame_time(o, o->last), b->in * 1e3, 100.0 * b->dripped / b->in, 100.0 * b->held / b->in,
               100.0 * b->evaporated / b->in);
    int runnel_texels;
    double spacing;
    soak_rain_frames_runnels(a->frames, &runnel_texels, &spacing);
    if (rc == SOAK_EXIT_OK && runnel_texels > 0)
        printf("runnels: the steady film breaks into rivulets on %d texels, %.1f mm apart; each frame's film\n"
               "gathers into them where it is below the minimum wetting rate\n",
               runnel_texels, spacing * 1e3);
    soak_rain_frames_destroy(a->frames);
    return rc;
}

/* --per-vertex: no map outputs, no sequence. */
static int per_vertex(const rain_args *a, const bake_opts *o)
{
    const char *maps[4] = {o->output, a->exposure_path, a->water_path, a->film_path};
    static const char *const names[4] = {"-o", "--exposure", "--water", "--film"};
    for (int k = 0; k < 4; ++k)
        if (maps[k]) {
            cli_error(CMD, "%s is not taken with --per-vertex: its map would be in the generated atlas, which no UV "
                      "set of the mesh matches", names[k]);
            return SOAK_EXIT_USAGE;
        }
    if (o->have_frames) {
        cli_error(CMD, "--frames is not taken with --per-vertex (one bake at the rain's end)");
        return SOAK_EXIT_USAGE;
    }
    if (a->uvo.uv.uv_index != 0 || a->uvo.uv.uv_name[0] || a->uvo.outside != SOAK_UV_WRAP) {
        cli_error(CMD, "--uv-set and --uv-outside are not taken with --per-vertex: it bakes in a generated atlas, "
                       "not the mesh's UVs");
        return SOAK_EXIT_USAGE;
    }
    int rc = bake_rain_budget(CMD, &a->p, o->width, o->height, 0, 0.0);
    return rc ? rc : bake_rain_vertex(a->mesh_path, &a->p, o, a->vertex_path, a->pov_name, &a->uvo);
}

int soak_bake_rain_main(int argc, char **argv)
{
    rain_args a;
    bake_opts o;
    int rc = parse_args(argc, argv, &a, &o);
    if (rc >= 0) return rc;
    if (a.vertex_path) return per_vertex(&a, &o);
    if (a.pov_name) {
        cli_error(CMD, "--pov-name is for --per-vertex OUT.inc (the POV-Ray mesh2's name)");
        return SOAK_EXIT_USAGE;
    }
    if ((rc = check_outputs(&a, &o)) != 0) return rc;
    long frames = o.have_frames ? o.last - o.first + 1 : 0;
    double last_time = o.have_frames ? fmax(bake_frame_time(&o, o.first), bake_frame_time(&o, o.last)) : 0.0;
    if ((rc = bake_rain_budget(CMD, &a.p, o.width, o.height, frames, last_time)) != 0) return rc;
    const char *paths[4] = {o.output, a.exposure_path, a.water_path, a.film_path};
    if (bake_uv_is_udim(o.output))
        return o.have_frames ? bake_rain_udim_frames(a.mesh_path, &a.p, &o, paths, &a.uvo)
                             : bake_rain_udim(a.mesh_path, &a.p, &o, paths, &a.uvo);
    if (o.have_frames) return run_frames(&a, &o);
    soak_rain_result res;
    if (bake(&a, &o, &res) != SOAK_OK) return SOAK_EXIT_FAIL;
    const soak_image *imgs[4] = {&res.wetness, &res.exposure, &res.water, &res.film};
    rc = bake_uv_verdict(CMD, a.mesh_path, &res.uv, &a.uvo) ||
                 bake_uv_dry_verdict(CMD, a.mesh_path, &res.exposure, &res.uv, &a.uvo)
             ? SOAK_EXIT_FAIL
             : write_outputs(paths, imgs, 4, o.float_exr);
    if (rc == SOAK_EXIT_OK) printf("%s: %ldx%ld rain wetness from %s\n", o.output, o.width, o.height, a.mesh_path);
    if (rc == SOAK_EXIT_OK) bake_uv_report(o.output, &res.uv);
    const soak_rain_runoff *r = &res.runoff;
    if (rc == SOAK_EXIT_OK && r->in > 0.0) /* m^3/s -> L/h */
        printf("steady rain on the mesh %.4g L/h: %.1f %% drips off, %.1f %% collects in puddles, %.1f %% evaporates\n",
               r->in * 3.6e6, 100.0 * r->dripped / r->in, 100.0 * r->held / r->in, 100.0 * r->evaporated / r->in);
    if (rc == SOAK_EXIT_OK && res.runnel_texels > 0)
        printf("runnels: the film broke into rivulets on %d texels, %.1f mm apart\n", res.runnel_texels,
               res.runnel_spacing * 1e3);
    soak_rain_result_free(&res);
    return rc;
}
