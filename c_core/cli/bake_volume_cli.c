/* soak bake volume: 3D parameter volumes for subsurface scattering of wet
 * materials (model in soak/bake_volume.h). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"
#include "soak/io_guard.h"
#include "soak/staged.h"
#include "soak/bake_volume.h"
#include "soak/preset.h"
#include "soak/units.h"

#define CMD "bake volume"
#define TABLE_ROWS 257 /* preset wetness table rows: steps of 1/256 in wetness */

typedef struct vol_args {
    const char *output, *map, *material, *liquid, *materials;
    int fmt_vdb, fmt_grid, fmt_df3;
    long dims[3];
    double size[3], depth, wetness;
    int unit_mm;
    int have_depth, have_wetness, noise, bits;
    long threads;
    soak_vol_turbulence turb;
    int have_dry_s, have_dry_a, have_wet_s, have_wet_a, have_raw;
    soak_vol_medium dry, wet;
} vol_args;

/* The box's extent and the penetration depth, in --unit. */
#define VOL_MIN_SIZE 1e-9
#define VOL_MAX_SIZE 1e9
/* A raw medium's phase lobes (the library's HG limit is SOAK_HG_G_MAX). */
#define VOL_MAX_G 0.999
/* soak_volume_alloc's cap: 2^31 floats over every channel. */
#define VOL_MAX_VOXELS ((double)((1L << 31) / SOAK_VOL_NCHANNELS))

static int read_size(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    double *out = ((vol_args *)dst)->size;
    soak_rgb c;
    const char *c1 = strchr(text, ','), *c2 = c1 ? strchr(c1 + 1, ',') : NULL;
    if (!c2 || strchr(c2 + 1, ',')) {
        cli_error(cmd, "%s: expected three comma-separated values, got '%s'", o->name, text);
        return 0;
    }
    if (!cli_parse_rgb(cmd, o->name, text, o->lo, o->hi, &c)) return 0;
    out[0] = c.r, out[1] = c.g, out[2] = c.b;
    return 1;
}

static int read_formats(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    (void)o;
    vol_args *a = dst;
    char buf[256], *parts[4];
    int n = cli_split_commas(text, buf, sizeof buf, parts, 3);
    a->fmt_vdb = a->fmt_grid = a->fmt_df3 = 0;
    for (int k = 0; k < n && k < 3; ++k) {
        if (strcmp(parts[k], "vdb") == 0) a->fmt_vdb = 1;
        else if (strcmp(parts[k], "grid") == 0) a->fmt_grid = 1;
        else if (strcmp(parts[k], "df3") == 0) a->fmt_df3 = 1;
        else {
            cli_error(cmd, "--format: unknown format '%s' (expected vdb, grid, df3)", parts[k]);
            return 0;
        }
    }
    if (n > 3) {
        cli_error(cmd, "--format: at most three formats, got '%s'", text);
        return 0;
    }
    return 1;
}

static int read_bits(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    long n;
    if (!cli_parse_int(cmd, o->name, text, 8, 32, &n) || (n != 8 && n != 16 && n != 32)) {
        cli_error(cmd, "--df3-bits: expected 8, 16 or 32, got '%s'", text);
        return 0;
    }
    ((vol_args *)dst)->bits = (int)n;
    return 1;
}

static const cli_choice units[] = {{"mm", 1, 0}, {"cm", 10, 0}, {"m", 1000, 0}, {NULL, 0, 0}};

#define F(field) CLI_FIELD(vol_args, field)
#define SEEN(field) CLI_SEEN(vol_args, field)
#define SIGMA(name, field, seen, help_)                                                                                \
    {name, NULL, CLI_OPT_RGB, .lo = 0, .hi = SOAK_VOL_SIGMA_MAX, F(field), SEEN(seen), .meta = "V|R,G,B", .help = help_}
#define LOBE(name, field, lo_, hi_, meta_, help_)                                                                      \
    {name, NULL, CLI_OPT_DOUBLE, .lo = lo_, .hi = hi_, F(field), SEEN(have_raw), .meta = meta_, .help = help_}
static const cli_opt volume_opts[] = {
    {"--output", "-o", CLI_OPT_STRING, F(output), .meta = "PREFIX", .help = "output prefix (folder must exist)"},
    {"--format", NULL, CLI_OPT_CUSTOM, .parse = read_formats, .meta = "LIST",
     .help = "comma list of vdb, grid, df3 (default: all three; vdb if built with OpenVDB)"},
    {"--dims", NULL, CLI_OPT_DIMS, .ihi = SOAK_VOLUME_MAX_DIM, .hi = VOL_MAX_VOXELS, F(dims), .meta = "NX,NY,NZ",
     .help = "voxels, %R each (default 64,64,32)"},
    {"--size", NULL, CLI_OPT_CUSTOM, .parse = read_size, .lo = VOL_MIN_SIZE, .hi = VOL_MAX_SIZE, .meta = "SX,SY,SZ",
     .help = "box extent in --unit (default 0.1,0.1,0.05)"},
    {"--unit", NULL, CLI_OPT_CHOICE, .choices = units, F(unit_mm), .meta = "mm|cm|m",
     .help = "length unit of --size, --depth and of the sigma values (default m)"},
    {"--depth", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = VOL_MAX_SIZE, F(depth), SEEN(have_depth), .meta = "D",
     .help = "penetration depth (default SZ/2)"},
    {"--map", NULL, CLI_OPT_STRING, F(map), .meta = "IMAGE",
     .help = "surface wetness map on the top face (column 0 at x=0, top row at y=SY)"},
    {"--wetness", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(wetness), SEEN(have_wetness), .meta = "W",
     .help = "uniform surface wetness %R (default 1, without --map)"},
    {"--noise", NULL, CLI_OPT_FLAG, .flag = 1, F(noise),
     .help = "3D noise wetness instead (Jensen et al. 1999's turbulence wetness),\nset by --seed and the noise options below"},
    {"--seed", NULL, CLI_OPT_INT, .ilo = 0, .ihi = INT64_MAX, F(turb.params.seed), .meta = "N",
     .help = "noise seed (default 0)"},
    {"--material", NULL, CLI_OPT_STRING, F(material), .meta = "NAME",
     .help = "preset (soak materials) soaked with --liquid NAME (default water)"},
    {"--liquid", NULL, CLI_OPT_STRING, F(liquid), .meta = "NAME", .help = "the liquid of --material"},
    {"--materials", NULL, CLI_OPT_STRING, F(materials), .meta = "FILE", .help = "another presets file"},
    {"--df3-bits", NULL, CLI_OPT_CUSTOM, .parse = read_bits, .meta = "8|16|32", .help = "df3 value size (default 16)"},
    {"--threads", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_BAKE_MAX_THREADS, F(threads), .meta = "N",
     .help = "worker threads, %R (default: every core)"},
    {"", NULL, CLI_OPT_HEADING, .help = "raw parameters instead of a preset (phase defaults: Jensen et al. 1999's paper):"},
    SIGMA("--dry-sigma-s", dry.sigma_s, have_dry_s, "dry scattering coefficient per --unit (without --material)"),
    SIGMA("--dry-sigma-a", dry.sigma_a, have_dry_a, "dry absorption coefficient per --unit (without --material)"),
    LOBE("--dry-g1", dry.g1, -VOL_MAX_G, VOL_MAX_G, "G", "first HG lobe of the dry phase, %R (default 0.05)"),
    LOBE("--dry-g2", dry.g2, -VOL_MAX_G, VOL_MAX_G, "G", "second lobe, %R (default -0.05)"),
    LOBE("--dry-w", dry.w, 0, 1, "W", "weight of the first lobe, %R (default 0.2)"),
    SIGMA("--wet-sigma-s", wet.sigma_s, have_wet_s, "wet scattering coefficient (default: the dry one)"),
    SIGMA("--wet-sigma-a", wet.sigma_a, have_wet_a, "wet absorption coefficient (default: the dry one)"),
    LOBE("--wet-g1", wet.g1, -VOL_MAX_G, VOL_MAX_G, "G", "first HG lobe of the wet phase, %R (default 0.8)"),
    LOBE("--wet-g2", wet.g2, -VOL_MAX_G, VOL_MAX_G, "G", "second lobe, %R (default -0.1)"),
    LOBE("--wet-w", wet.w, 0, 1, "W", "weight of the first lobe, %R (default 0.1)"),
    {"", NULL, CLI_OPT_HEADING, .help = "noise (with --noise):"},
};
#undef SIGMA
#undef LOBE
#undef F
#undef SEEN

#define VOLUME_TABLES(a, turb) {CLI_TABLE(volume_opts, (a)), BAKE_NOISE_TABLE(turb)}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak bake volume -o PREFIX [options]\n\n"
            "Voxel grids of sigma_s, sigma_a (RGB), g1, g2, w (two-term Henyey-Greenstein) and\n"
            "wetness over a box [0,SX]x[0,SY]x[0,SZ], z up, wetted from its top face. Water\n"
            "reaches the penetration depth D below a wet surface with the profile\n"
            "p(d) = 1 - (3t^2 - 2t^3), t = d/D (saturated skin, smooth front; see\n"
            "soak/bake_volume.h). Parameters follow wetness through the material preset's\n"
            "wetness table (soak/wetness.h) or linearly between raw dry and wet values.\n\n"
            "output (-o PREFIX):\n"
            "  PREFIX.vdb                  OpenVDB float grids density, sigma_s, sigma_a, sigma_s_r.., g1, g2, w, wetness\n"
            "  PREFIX.json + PREFIX.raw    soak grid for the reference tracer (float32, documented in the .json)\n"
            "  PREFIX_<channel>.df3        POV-Ray density files, + PREFIX_df3.json (scales) and PREFIX.inc\n\n"
            "options:\n");
    const cli_opt_table tables[] = VOLUME_TABLES(NULL, NULL);
    cli_opts_help(out, tables, sizeof tables / sizeof tables[0]);
    fprintf(out, "\nexamples:\n"
                 "  soak bake volume --material sand --map wet.png --size 0.2,0.2,0.05 --depth 0.01 -o vol/sand\n"
                 "  soak bake volume --dry-sigma-s 120 --dry-sigma-a 2 --wet-g1 0.8 --noise --seed 3 \\\n"
                 "       --format vdb,df3 --dims 128,128,32 -o vol/beach\n");
}

static void defaults(vol_args *a)
{
    memset(a, 0, sizeof *a);
    a->fmt_vdb = soak_volume_have_vdb();
    a->fmt_grid = a->fmt_df3 = 1;
    a->dims[0] = a->dims[1] = 64;
    a->dims[2] = 32;
    a->size[0] = a->size[1] = 0.1;
    a->size[2] = 0.05;
    a->unit_mm = 1000;
    a->wetness = 1.0;
    a->bits = 16;
    a->liquid = "water";
    soak_turbulence_defaults(&a->turb.params);
    /* [JLD99] sec. 4.1, wet paper */
    a->dry.g1 = 0.05, a->dry.g2 = -0.05, a->dry.w = 0.2;
    a->wet.g1 = 0.8, a->wet.g2 = -0.1, a->wet.w = 0.1;
}

/* Returns -1 to go on, else the exit code. */
static int parse_args(int argc, char **argv, vol_args *a)
{
    defaults(a);
    const cli_spec spec = BAKE_SPEC(CMD, usage, NULL, NULL);
    const cli_opt_table tables[] = VOLUME_TABLES(a, &a->turb.params);
    int rc = cli_opts_parse(&spec, tables, sizeof tables / sizeof tables[0], argc, argv);
    a->have_raw |= a->have_dry_s || a->have_dry_a || a->have_wet_s || a->have_wet_a;
    return rc;
}

typedef struct progress_ctx {
    cli_progress bar;
} progress_ctx;

static void on_progress(void *user, double fraction)
{
    cli_progress_update(&((progress_ctx *)user)->bar, fraction);
}

/* Every output path of the requested formats: folder writable (else exit
 * 1), not the input map (else exit 2). 0 when fine. */
static int check_outputs(const vol_args *a)
{
    static const char *const suffix[] = {".vdb", ".json", ".raw", "_df3.json", ".inc"};
    const int wanted[] = {a->fmt_vdb, a->fmt_grid, a->fmt_grid, a->fmt_df3, a->fmt_df3};
    char path[4352], err[4608];
    if (strlen(a->output) > 4000) {
        cli_error(CMD, "-o: prefix too long");
        return SOAK_EXIT_USAGE;
    }
    const char *slash = strrchr(a->output, '/');
    const char *name = slash ? slash + 1 : a->output;
    if (!*name || !strcmp(name, ".") || !strcmp(name, "..")) {
        cli_error(CMD, "-o '%s': needs a file name prefix after the folder, e.g. '%s%sbox'", a->output, a->output,
                  *name && !slash ? "/" : "");
        return SOAK_EXIT_USAGE;
    }
    char presets[SOAK_PRESETS_PATH_MAX] = ""; /* not found: soak_presets_load says so */
    if (a->material && !a->materials) soak_presets_default_path(presets, sizeof presets, NULL, 0);
    soak_io_guard g;
    soak_io_guard_init(&g);
    int ok = soak_io_guard_input(&g, "--map", a->map) == SOAK_OK &&
             soak_io_guard_input(&g, a->materials ? "--materials" : "presets file ($SOAK_MATERIALS or the shipped one)",
                                 a->material ? (a->materials ? a->materials : presets) : NULL) == SOAK_OK;
    for (int k = 0; k < 5 + SOAK_VOL_NCHANNELS; ++k) {
        if (k < 5) {
            if (!wanted[k]) continue;
            snprintf(path, sizeof path, "%s%s", a->output, suffix[k]);
        } else {
            if (!a->fmt_df3) continue;
            snprintf(path, sizeof path, "%s_%s.df3", a->output, soak_volume_channel_name(k - 5));
        }
        if (soak_path_check_writable(path, err, sizeof err) != SOAK_OK) {
            cli_error(CMD, "-o: %s", err);
            soak_io_guard_free(&g);
            return SOAK_EXIT_FAIL;
        }
        ok = ok && soak_io_guard_output(&g, "-o", path) == SOAK_OK;
    }
    soak_status st = ok ? soak_io_guard_check(&g, err, sizeof err) : SOAK_ERR_NOMEM;
    soak_io_guard_free(&g);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", st == SOAK_ERR_NOMEM ? "out of memory" : err);
        return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    }
    return 0;
}

static int build_rows(const vol_args *a, soak_vol_medium **rows, int *n_rows)
{
    char err[4352] = "";
    if (a->material) {
        soak_preset_db *db = NULL;
        soak_status st = soak_presets_load(a->materials, &db, err, sizeof err);
        if (st != SOAK_OK) {
            cli_error(CMD, "--materials: %s", err[0] ? err : soak_status_str(st));
            return SOAK_EXIT_FAIL;
        }
        const soak_preset *p = soak_presets_find(db, a->material);
        const soak_liquid *l = soak_presets_find_liquid(db, a->liquid);
        int rc = 0;
        if (!p) {
            cli_error(CMD, "--material: no preset named '%s' in %s (see soak materials)", a->material,
                      soak_presets_path(db));
            rc = SOAK_EXIT_USAGE;
        } else if (!l) {
            cli_error(CMD, "--liquid: no liquid named '%s' in %s", a->liquid, soak_presets_path(db));
            rc = SOAK_EXIT_USAGE;
        } else if (p->kind == SOAK_KIND_CONDUCTOR) {
            cli_error(CMD, "--material: '%s' is a conductor: it has no subsurface medium to bake", a->material);
            rc = SOAK_EXIT_USAGE;
        } else {
            *rows = malloc(TABLE_ROWS * sizeof **rows);
            *n_rows = TABLE_ROWS;
            st = *rows ? soak_vol_rows_from_preset(p, l, soak_m_from_mm(a->unit_mm), TABLE_ROWS, *rows) : SOAK_ERR_NOMEM;
            if (st != SOAK_OK) {
                cli_error(CMD, "--material '%s': wetness table failed: %s", a->material, soak_status_str(st));
                rc = SOAK_EXIT_FAIL;
            }
        }
        soak_presets_free(db);
        return rc;
    }
    *rows = malloc(2 * sizeof **rows);
    if (!*rows) return SOAK_EXIT_FAIL;
    (*rows)[0] = a->dry;
    (*rows)[1] = a->wet;
    if (!a->have_wet_s) (*rows)[1].sigma_s = a->dry.sigma_s;
    if (!a->have_wet_a) (*rows)[1].sigma_a = a->dry.sigma_a;
    *n_rows = 2;
    return 0;
}

static int validate(vol_args *a)
{
    if (!a->output) {
        cli_error(CMD, "-o/--output PREFIX is required (see --help)");
        return 0;
    }
    if (!a->fmt_vdb && !a->fmt_grid && !a->fmt_df3) {
        cli_error(CMD, "--format: no format selected");
        return 0;
    }
    if (a->fmt_vdb && !soak_volume_have_vdb()) {
        cli_error(CMD, "--format vdb: this build has no OpenVDB support (use --format grid,df3)");
        return 0;
    }
    if (a->material && a->have_raw) {
        cli_error(CMD, "--material and --dry-*/--wet-* parameters exclude each other");
        return 0;
    }
    if (!a->material && !(a->have_dry_s && a->have_dry_a)) {
        cli_error(CMD, "give --material NAME, or --dry-sigma-s and --dry-sigma-a (see --help)");
        return 0;
    }
    if (!!a->map + !!a->noise + !!a->have_wetness > 1) {
        cli_error(CMD, "--map, --noise and --wetness exclude each other");
        return 0;
    }
    if (!a->have_depth) a->depth = 0.5 * a->size[2];
    a->turb.length = a->size[0];
    if (a->noise && soak_vol_turbulence_check(&a->turb) != SOAK_OK) {
        cli_error(CMD, "--frequency/--lacunarity/--octaves: frequency * lacunarity^(octaves-1) must be <= 20000");
        return 0;
    }
    return 1;
}

/* What a bake holds: the wetness table, the map and the volume. */
typedef struct vol_work {
    soak_vol_medium *rows;
    int n_rows;
    soak_image map;
    soak_volume v;
} vol_work;

/* Rows, map and the allocated volume. Returns 0 or the exit code. */
static int prepare(const vol_args *a, vol_work *w)
{
    int rc = build_rows(a, &w->rows, &w->n_rows);
    if (rc) return rc;
    char err[4352] = "";
    if (a->map && soak_image_read(a->map, &w->map, err, sizeof err) != SOAK_OK) {
        cli_error(CMD, "--map: %s", err);
        return SOAK_EXIT_FAIL;
    }
    soak_status st = soak_volume_alloc(&w->v, (int)a->dims[0], (int)a->dims[1], (int)a->dims[2], a->size);
    if (st != SOAK_OK) {
        cli_error(CMD, "--dims %ldx%ldx%ld: %s", a->dims[0], a->dims[1], a->dims[2],
                  st == SOAK_ERR_NOMEM ? "out of memory" : "too many voxels (at most 2^31 / 10)");
        return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    }
    return 0;
}

static int bake(vol_args *a, vol_work *w)
{
    soak_volume_source src = {a->map ? &w->map : NULL, a->wetness, a->depth,
                              a->noise ? soak_vol_turbulence_wetness : NULL, &a->turb};
    progress_ctx prog;
    cli_progress_start(&prog.bar, CMD, 1.0);
    soak_bake_exec exec = {(int)a->threads, on_progress, &prog};
    soak_status st = soak_volume_bake(&w->v, w->rows, w->n_rows, &src, &exec);
    cli_progress_finish(&prog.bar);
    if (st == SOAK_OK) return 0;
    cli_error(CMD, "%s", st == SOAK_ERR_ARG && a->map ? "--map: the map holds NaN values" : soak_status_str(st));
    return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
}

/* Every format is staged, then all are renamed together: a failure keeps
 * every previous output and leaves no new file. */
static int write_formats(const vol_args *a, const vol_work *w)
{
    soak_staged stage;
    soak_staged_init(&stage);
    char path[4352], err[4352] = "";
    soak_status st = SOAK_OK;
    if (a->fmt_vdb) {
        snprintf(path, sizeof path, "%s.vdb", a->output);
        st = soak_volume_stage_vdb(&stage, &w->v, path, err, sizeof err);
    }
    if (st == SOAK_OK && a->fmt_grid)
        st = soak_volume_stage_grid(&stage, &w->v, a->output, w->rows, w->n_rows, a->depth, err, sizeof err);
    if (st == SOAK_OK && a->fmt_df3) st = soak_volume_stage_df3(&stage, &w->v, a->output, a->bits, err, sizeof err);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return bake_fail(CMD, st, err);
    }
    if ((st = soak_staged_commit(&stage, err, sizeof err)) != SOAK_OK) return bake_fail(CMD, st, err);
    printf("%s: %dx%dx%d voxels,%s%s%s\n", a->output, w->v.nx, w->v.ny, w->v.nz, a->fmt_vdb ? " vdb" : "",
           a->fmt_grid ? " grid" : "", a->fmt_df3 ? " df3" : "");
    return 0;
}

int soak_bake_volume_main(int argc, char **argv)
{
    vol_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc >= 0) return rc;
    if (!validate(&a)) return SOAK_EXIT_USAGE;
    if ((rc = check_outputs(&a)) != 0) return rc;
    vol_work w;
    memset(&w, 0, sizeof w);
    if ((rc = prepare(&a, &w)) == 0 && (rc = bake(&a, &w)) == 0) rc = write_formats(&a, &w);
    soak_volume_free(&w.v);
    soak_image_free(&w.map);
    free(w.rows);
    return rc;
}
