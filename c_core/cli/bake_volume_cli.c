/* soak bake volume: 3D parameter volumes for subsurface scattering of wet
 * materials (model in soak/bake_volume.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_cli.h"
#include "cli.h"
#include "soak/io_guard.h"
#include "soak/staged.h"
#include "soak/bake_volume.h"
#include "soak/preset.h"

#define CMD "bake volume"
#define TABLE_ROWS 257 /* preset wetness table rows: steps of 1/256 in wetness */

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
            "options:\n"
            "  -o, --output PREFIX   output prefix (folder must exist)\n"
            "  --format LIST         comma list of vdb, grid, df3 (default: all three; vdb if built with OpenVDB)\n"
            "  --dims NX,NY,NZ       voxels, 1..4096 each (default 64,64,32)\n"
            "  --size SX,SY,SZ       box extent in --unit (default 0.1,0.1,0.05)\n"
            "  --unit mm|cm|m        length unit of --size, --depth and of the sigma values (default m)\n"
            "  --depth D             penetration depth (default SZ/2)\n"
            "  --map IMAGE           surface wetness map on the top face (column 0 at x=0, top row at y=SY)\n"
            "  --wetness W           uniform surface wetness 0..1 (default 1, without --map)\n"
            "  --noise               3D noise wetness instead (seed 000's turbulence wetness);\n"
            "                        with --seed N, --turbulence, --octaves N, --frequency F (cells per SX),\n"
            "                        --lacunarity L, --gain G, --threshold T, --softness S\n"
            "  --material NAME       preset (soak materials) soaked with --liquid NAME (default water);\n"
            "                        --materials FILE selects another presets file\n"
            "  --dry-sigma-s V|R,G,B --dry-sigma-a V|R,G,B --dry-g1 G --dry-g2 G --dry-w W\n"
            "  --wet-sigma-s ..      --wet-sigma-a ..      --wet-g1 G --wet-g2 G --wet-w W\n"
            "                        raw parameters instead of a preset (sigma per --unit); wet values\n"
            "                        default to the dry ones; g1/g2/w default to seed 000's paper\n"
            "                        (dry 0.05, -0.05, 0.2; wet 0.8, -0.1, 0.1)\n"
            "  --df3-bits 8|16|32    df3 value size (default 16)\n"
            "  --threads N           worker threads (default: every core)\n\n"
            "examples:\n"
            "  soak bake volume --material sand --map wet.png --size 0.2,0.2,0.05 --depth 0.01 -o vol/sand\n"
            "  soak bake volume --dry-sigma-s 120 --dry-sigma-a 2 --wet-g1 0.8 --noise --seed 3 \\\n"
            "       --format vdb,df3 --dims 128,128,32 -o vol/beach\n");
}

typedef struct vol_args {
    const char *output, *map, *material, *liquid, *materials;
    int fmt_vdb, fmt_grid, fmt_df3;
    long dims[3];
    double size[3], unit_mm, depth, wetness;
    int have_depth, have_wetness, noise, bits;
    long threads;
    soak_vol_turbulence turb;
    int have_dry_s, have_dry_a, have_wet_s, have_wet_a, have_raw;
    soak_vol_medium dry, wet;
    int wet_phase_set[3];
} vol_args;

static int parse_triple(const char *opt, const char *text, double lo, double hi, double out[3])
{
    soak_rgb c;
    const char *c1 = strchr(text, ','), *c2 = c1 ? strchr(c1 + 1, ',') : NULL;
    if (!c2 || strchr(c2 + 1, ',')) {
        cli_error(CMD, "%s: expected three comma-separated values, got '%s'", opt, text);
        return 0;
    }
    if (!cli_parse_rgb(CMD, opt, text, lo, hi, &c)) return 0;
    out[0] = c.r, out[1] = c.g, out[2] = c.b;
    return 1;
}

static int parse_formats(vol_args *a, const char *text)
{
    char buf[256], *parts[4];
    int n = cli_split_commas(text, buf, sizeof buf, parts, 3);
    a->fmt_vdb = a->fmt_grid = a->fmt_df3 = 0;
    for (int k = 0; k < n && k < 3; ++k) {
        if (strcmp(parts[k], "vdb") == 0) a->fmt_vdb = 1;
        else if (strcmp(parts[k], "grid") == 0) a->fmt_grid = 1;
        else if (strcmp(parts[k], "df3") == 0) a->fmt_df3 = 1;
        else {
            cli_error(CMD, "--format: unknown format '%s' (expected vdb, grid, df3)", parts[k]);
            return 0;
        }
    }
    if (n > 3) {
        cli_error(CMD, "--format: at most three formats, got '%s'", text);
        return 0;
    }
    return 1;
}

/* Options with one value. Returns 1 consumed, 0 not ours, -1 error. */
static int parse_valued(vol_args *a, int argc, char **argv, int *i)
{
    const char *o = argv[*i], *v;
    static const char *const names[] = {"-o", "--output", "--format", "--dims", "--size", "--unit", "--depth", "--map",
                                        "--wetness", "--material", "--liquid", "--materials", "--df3-bits", "--threads",
                                        "--seed", "--octaves", "--frequency", "--lacunarity", "--gain", "--threshold",
                                        "--softness", "--dry-sigma-s", "--dry-sigma-a", "--dry-g1", "--dry-g2",
                                        "--dry-w", "--wet-sigma-s", "--wet-sigma-a", "--wet-g1", "--wet-g2", "--wet-w"};
    const char *name = NULL;
    for (size_t k = 0; k < sizeof names / sizeof names[0] && !name; ++k)
        if (cli_is(o, names[k])) name = names[k];
    if (!name) return 0;
    if (!(v = cli_value(CMD, argc, argv, i))) return -1;
    long n;
    double d;
    soak_turbulence_params *t = &a->turb.params;
    if (!strcmp(name, "-o") || !strcmp(name, "--output")) a->output = v;
    else if (!strcmp(name, "--format")) return parse_formats(a, v) ? 1 : -1;
    else if (!strcmp(name, "--dims")) {
        /* soak_volume_alloc's cap: 2^31 floats over every channel */
        if (!cli_parse_dims(CMD, name, v, SOAK_VOLUME_MAX_DIM, (double)((1L << 31) / SOAK_VOL_NCHANNELS), a->dims))
            return -1;
    } else if (!strcmp(name, "--size")) {
        if (!parse_triple(name, v, 1e-9, 1e9, a->size)) return -1;
    } else if (!strcmp(name, "--unit")) {
        if (!strcmp(v, "mm")) a->unit_mm = 1;
        else if (!strcmp(v, "cm")) a->unit_mm = 10;
        else if (!strcmp(v, "m")) a->unit_mm = 1000;
        else {
            cli_error(CMD, "--unit: expected mm, cm or m, got '%s'", v);
            return -1;
        }
    } else if (!strcmp(name, "--depth")) {
        if (!cli_parse_double(CMD, name, v, 0, 1e9, &a->depth)) return -1;
        a->have_depth = 1;
    } else if (!strcmp(name, "--map")) a->map = v;
    else if (!strcmp(name, "--wetness")) {
        if (!cli_parse_double(CMD, name, v, 0, 1, &a->wetness)) return -1;
        a->have_wetness = 1;
    } else if (!strcmp(name, "--material")) a->material = v;
    else if (!strcmp(name, "--liquid")) a->liquid = v;
    else if (!strcmp(name, "--materials")) a->materials = v;
    else if (!strcmp(name, "--df3-bits")) {
        if (!cli_parse_int(CMD, name, v, 8, 32, &n) || (n != 8 && n != 16 && n != 32)) {
            cli_error(CMD, "--df3-bits: expected 8, 16 or 32, got '%s'", v);
            return -1;
        }
        a->bits = (int)n;
    } else if (!strcmp(name, "--threads")) {
        if (!cli_parse_int(CMD, name, v, 1, SOAK_BAKE_MAX_THREADS, &a->threads)) return -1;
    } else if (!strcmp(name, "--seed")) {
        if (!cli_parse_int(CMD, name, v, 0, 0x7fffffffffffffffL, &n)) return -1;
        t->seed = (uint64_t)n;
    } else if (!strcmp(name, "--octaves")) {
        if (!cli_parse_int(CMD, name, v, 1, 24, &n)) return -1;
        t->octaves = (int)n;
    } else if (!strcmp(name, "--frequency")) {
        if (!cli_parse_double(CMD, name, v, 1e-6, 8192, &t->frequency)) return -1;
    } else if (!strcmp(name, "--lacunarity")) {
        if (!cli_parse_double(CMD, name, v, 1, 16, &t->lacunarity)) return -1;
    } else if (!strcmp(name, "--gain")) {
        if (!cli_parse_double(CMD, name, v, 0, 1, &t->gain)) return -1;
    } else if (!strcmp(name, "--threshold")) {
        if (!cli_parse_double(CMD, name, v, -2, 2, &t->threshold)) return -1;
        t->thresholded = 1;
    } else if (!strcmp(name, "--softness")) {
        if (!cli_parse_double(CMD, name, v, 0, 2, &t->softness)) return -1;
    } else {
        /* raw medium parameters */
        int wet = !strncmp(name, "--wet-", 6);
        soak_vol_medium *m = wet ? &a->wet : &a->dry;
        const char *field = name + 6;
        a->have_raw = 1;
        if (!strcmp(field, "sigma-s") || !strcmp(field, "sigma-a")) {
            int s = field[6] == 's';
            if (!cli_parse_rgb(CMD, name, v, 0, SOAK_VOL_SIGMA_MAX, s ? &m->sigma_s : &m->sigma_a)) return -1;
            if (wet) *(s ? &a->have_wet_s : &a->have_wet_a) = 1;
            else *(s ? &a->have_dry_s : &a->have_dry_a) = 1;
        } else {
            int k = !strcmp(field, "g1") ? 0 : (!strcmp(field, "g2") ? 1 : 2);
            double lo = k == 2 ? 0.0 : -0.999, hi = k == 2 ? 1.0 : 0.999;
            if (!cli_parse_double(CMD, name, v, lo, hi, &d)) return -1;
            *(k == 0 ? &m->g1 : (k == 1 ? &m->g2 : &m->w)) = d;
        }
    }
    return 1;
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
    /* seed 000 sec. 4.1, wet paper */
    a->dry.g1 = 0.05, a->dry.g2 = -0.05, a->dry.w = 0.2;
    a->wet.g1 = 0.8, a->wet.g2 = -0.1, a->wet.w = 0.1;
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
    soak_io_guard g;
    soak_io_guard_init(&g);
    int ok = soak_io_guard_input(&g, "--map", a->map) == SOAK_OK &&
             soak_io_guard_input(&g, a->materials ? "--materials" : "presets file ($SOAK_MATERIALS or the shipped one)",
                                 a->material ? (a->materials ? a->materials : soak_presets_default_path()) : NULL) ==
                 SOAK_OK;
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
            st = *rows ? soak_vol_rows_from_preset(p, l, a->unit_mm, TABLE_ROWS, *rows) : SOAK_ERR_NOMEM;
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

int soak_bake_volume_main(int argc, char **argv)
{
    vol_args a;
    defaults(&a);
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            usage(stdout);
            return SOAK_EXIT_OK;
        }
        if (!strcmp(o, "--noise")) {
            a.noise = 1;
            continue;
        }
        if (!strcmp(o, "--turbulence")) {
            a.turb.params.sum = SOAK_NOISE_TURBULENCE;
            continue;
        }
        int r = parse_valued(&a, argc, argv, &i);
        if (r < 0) return SOAK_EXIT_USAGE;
        if (r == 0) {
            cli_error(CMD, "unknown option '%s' (see --help)", o);
            return SOAK_EXIT_USAGE;
        }
    }
    if (!validate(&a)) return SOAK_EXIT_USAGE;
    int rc = check_outputs(&a);
    if (rc) return rc;

    soak_vol_medium *rows = NULL;
    int n_rows = 0;
    rc = build_rows(&a, &rows, &n_rows);
    if (rc) {
        free(rows);
        return rc;
    }
    char err[4352] = "";
    soak_image map = {0, 0, 0, NULL};
    soak_status st = SOAK_OK;
    if (a.map && (st = soak_image_read(a.map, &map, err, sizeof err)) != SOAK_OK) {
        cli_error(CMD, "--map: %s", err);
        free(rows);
        return SOAK_EXIT_FAIL;
    }
    soak_volume v;
    st = soak_volume_alloc(&v, (int)a.dims[0], (int)a.dims[1], (int)a.dims[2], a.size);
    if (st != SOAK_OK) {
        cli_error(CMD, "--dims %ldx%ldx%ld: %s", a.dims[0], a.dims[1], a.dims[2],
                  st == SOAK_ERR_NOMEM ? "out of memory" : "too many voxels (at most 2^31 / 10)");
        soak_image_free(&map);
        free(rows);
        return st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    }
    soak_volume_source src = {a.map ? &map : NULL, a.wetness, a.depth,
                              a.noise ? soak_vol_turbulence_wetness : NULL, &a.turb};
    progress_ctx prog;
    cli_progress_start(&prog.bar, CMD, 1.0);
    soak_bake_exec exec = {(int)a.threads, on_progress, &prog};
    st = soak_volume_bake(&v, rows, n_rows, &src, &exec);
    cli_progress_finish(&prog.bar);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", st == SOAK_ERR_ARG && a.map ? "--map: the map holds NaN values" : soak_status_str(st));
        rc = st == SOAK_ERR_ARG ? SOAK_EXIT_USAGE : SOAK_EXIT_FAIL;
    }
    /* Every format is staged, then all are renamed together: a failure
     * keeps every previous output and leaves no new file. */
    soak_staged stage;
    soak_staged_init(&stage);
    char path[4352];
    if (!rc && a.fmt_vdb) {
        snprintf(path, sizeof path, "%s.vdb", a.output);
        st = soak_volume_stage_vdb(&stage, &v, path, err, sizeof err);
        if (st != SOAK_OK) rc = bake_fail(CMD, st, err);
    }
    if (!rc && a.fmt_grid) {
        st = soak_volume_stage_grid(&stage, &v, a.output, rows, n_rows, a.depth, err, sizeof err);
        if (st != SOAK_OK) rc = bake_fail(CMD, st, err);
    }
    if (!rc && a.fmt_df3) {
        st = soak_volume_stage_df3(&stage, &v, a.output, a.bits, err, sizeof err);
        if (st != SOAK_OK) rc = bake_fail(CMD, st, err);
    }
    if (rc) {
        soak_staged_abort(&stage);
    } else if ((st = soak_staged_commit(&stage, err, sizeof err)) != SOAK_OK) {
        rc = bake_fail(CMD, st, err);
    } else {
        printf("%s: %dx%dx%d voxels,%s%s%s\n", a.output, v.nx, v.ny, v.nz, a.fmt_vdb ? " vdb" : "",
               a.fmt_grid ? " grid" : "", a.fmt_df3 ? " df3" : "");
    }
    soak_volume_free(&v);
    soak_image_free(&map);
    free(rows);
    return rc;
}
