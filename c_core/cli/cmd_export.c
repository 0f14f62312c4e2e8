/* soak export: the core's data for the renderer front ends, one target
 * writer per renderer (soak/export.h). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "soak/io_guard.h"
#include "soak/export.h"
#include "soak/preset.h"
#include "soak/preset_variant.h"

static const char *CMD = "export";

#define EXPORT_VARIANTS_MAX 64

typedef struct export_args {
    const char *target, *output, *file;
    const char *variants[EXPORT_VARIANTS_MAX];
    int n_variants;
} export_args;

/* Kept as text: read against the presets once they are loaded. */
static int read_variant(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    (void)o;
    export_args *a = dst;
    if (a->n_variants == EXPORT_VARIANTS_MAX) {
        cli_error(cmd, "--variant: at most %d variants", EXPORT_VARIANTS_MAX);
        return 0;
    }
    a->variants[a->n_variants++] = text;
    return 1;
}

static int read_output(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    (void)o;
    if (!text[0]) {
        cli_error(cmd, "-o: empty file name");
        return 0;
    }
    ((export_args *)dst)->output = text;
    return 1;
}

#define F(field) CLI_FIELD(export_args, field)
static const cli_opt export_opts[] = {
    {"--target", NULL, CLI_OPT_STRING, F(target), .meta = "NAME", .help = "one of the targets below (required)"},
    {"--output", "-o", CLI_OPT_CUSTOM, .parse = read_output, .meta = "FILE",
     .help = "where to write (default: stdout); written to a temporary\n"
             "file and renamed, so a failure leaves FILE untouched"},
    {"--materials", NULL, CLI_OPT_STRING, F(file), .meta = "FILE",
     .help = "preset file (default: $SOAK_MATERIALS, else the shipped\ndata/materials.json)"},
    {"--variant", NULL, CLI_OPT_CUSTOM, .parse = read_variant, .meta = "NAME=BASE,KEY=V[,KEY=V]",
     .help = "adds preset NAME, a copy of preset BASE with KEY changed\n"
             "(repeatable, up to 64): porosity=P, the open porosity in\n"
             "[0.001, 0.95] or 0 (no pores; porous_dielectric only), the\n"
             "wet roughness ggx_alpha_dry sqrt(1 - P) and extinction\n"
             "x (1 - P)/(1 - P_base) following it; film_mm=H, the film's\n"
             "depth in [0, 1000] mm. The chain derives the rest."},
};
#undef F

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak export --target NAME [-o FILE] [--materials FILE]\n"
            "                   [--variant NAME=BASE,KEY=V[,KEY=V]]...\n\n"
            "Writes what a renderer front end needs, computed by the core from the\n"
            "one preset file: per preset and liquid, the wetness -> parameter tables\n"
            "(non-uniform knots that include each preset's saturation point), and the\n"
            "wetness function for any base colour. Same input, same bytes.\n"
            "--variant adds presets that differ from one in the file by their porosity\n"
            "or film depth ([Hnat06] Fig. 5 sweeps the one, [Lag13] the other).\n\n"
            "options:\n");
    const cli_opt_table tables[] = {CLI_TABLE(export_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out, "\ntargets:\n");
    int n = 0;
    const soak_export_target *t = soak_export_targets(&n);
    for (int i = 0; i < n; ++i) fprintf(out, "  %-8s %s\n", t[i].name, t[i].summary);
    fprintf(out, "\nexamples:\n"
                 "  soak export --target json -o soak_export.json\n"
                 "  soak export --target povray -o povray/soak_materials.inc\n"
                 "  soak export --target povray -o pots.inc --variant clay_p10=clay,porosity=0.1 \\\n"
                 "      --variant clay_p50=clay,porosity=0.5\n");
}

/* Returns -1 with *target found, else the exit code. */
static int parse_args(int argc, char **argv, export_args *a, const soak_export_target **target)
{
    memset(a, 0, sizeof *a);
    const cli_spec spec = {CMD, "argument", "'soak export --help'", usage, NULL, NULL};
    const cli_opt_table tables[] = {CLI_TABLE(export_opts, a)};
    int rc = cli_opts_parse(&spec, tables, 1, argc, argv);
    if (rc >= 0) return rc;
    if (!a->target) {
        cli_error(CMD, "--target is required (see 'soak export --help')");
        return SOAK_EXIT_USAGE;
    }
    if (!(*target = soak_export_find_target(a->target))) {
        cli_error(CMD, "--target: unknown target '%s' (see 'soak export --help')", a->target);
        return SOAK_EXIT_USAGE;
    }
    return -1;
}

static soak_status add_variants(const export_args *a, soak_preset_db *db, char *err, size_t errlen)
{
    for (int i = 0; i < a->n_variants; ++i) {
        char name[SOAK_PRESET_NAME_MAX], base[SOAK_PRESET_NAME_MAX];
        soak_preset_change change;
        soak_status st = soak_preset_variant_parse(a->variants[i], name, base, &change, err, errlen);
        if (st == SOAK_OK) st = soak_presets_add_variant(db, name, base, &change, err, errlen);
        if (st != SOAK_OK) {
            cli_error(CMD, "--variant %s: %s", a->variants[i], err);
            return st;
        }
    }
    return SOAK_OK;
}

int soak_cmd_export(int argc, char **argv)
{
    export_args a;
    const soak_export_target *target = NULL;
    int rc = parse_args(argc, argv, &a, &target);
    if (rc >= 0) return rc;
    char err[4352] = "";
    int to_file = a.output && strcmp(a.output, "-") != 0;
    if (to_file) {
        char presets[SOAK_PRESETS_PATH_MAX] = ""; /* not found: soak_presets_load says so below */
        if (!a.file) soak_presets_default_path(presets, sizeof presets, NULL, 0);
        const char *inputs[1] = {a.file ? a.file : presets};
        if (soak_io_check_output("-o", a.output, inputs, 1, err, sizeof err) != SOAK_OK) {
            cli_error(CMD, "%s (--materials or $SOAK_MATERIALS)", err);
            return SOAK_EXIT_USAGE;
        }
    }
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(a.file, &db, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    st = add_variants(&a, db, err, sizeof err);
    if (st != SOAK_OK) {
        soak_presets_free(db);
        return SOAK_EXIT_USAGE;
    }
    err[0] = '\0';
    st = soak_export_run(target, db, a.output, err, sizeof err);
    soak_presets_free(db);
    if (st != SOAK_OK) {
        cli_error(CMD, "--target %s: %s", a.target, err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    if (to_file) fprintf(stderr, "soak export: wrote %s\n", a.output);
    return SOAK_EXIT_OK;
}
