/* soak export: the core's data for the renderer front ends, one target
 * writer per renderer (soak/export.h). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "soak/io_guard.h"
#include "soak/export.h"
#include "soak/preset.h"

static const char *CMD = "export";

typedef struct export_args {
    const char *target, *output, *file;
} export_args;

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
};
#undef F

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak export --target NAME [-o FILE] [--materials FILE]\n\n"
            "Writes what a renderer front end needs, computed by the core from the\n"
            "one preset file: per preset and liquid, the wetness -> parameter tables\n"
            "(non-uniform knots that include each preset's saturation point), and the\n"
            "wetness function for any base colour. Same input, same bytes.\n\n"
            "options:\n");
    const cli_opt_table tables[] = {CLI_TABLE(export_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out, "\ntargets:\n");
    int n = 0;
    const soak_export_target *t = soak_export_targets(&n);
    for (int i = 0; i < n; ++i) fprintf(out, "  %-8s %s\n", t[i].name, t[i].summary);
    fprintf(out, "\nexamples:\n"
                 "  soak export --target json -o soak_export.json\n"
                 "  soak export --target povray -o povray/soak_materials.inc\n");
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
