/* soak export: the core's data for the renderer front ends, one target
 * writer per renderer (soak/export.h). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "soak/io_guard.h"
#include "soak/export.h"
#include "soak/preset.h"

static const char *CMD = "export";

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak export --target NAME [-o FILE] [--materials FILE]\n\n"
            "Writes what a renderer front end needs, computed by the core from the\n"
            "one preset file: per preset and liquid, the wetness -> parameter tables\n"
            "(non-uniform knots that include each preset's saturation point), and the\n"
            "wetness function for any base colour. Same input, same bytes.\n\n"
            "options:\n"
            "  --target NAME     one of:\n");
    int n = 0;
    const soak_export_target *t = soak_export_targets(&n);
    for (int i = 0; i < n; ++i) fprintf(out, "                      %-8s %s\n", t[i].name, t[i].summary);
    fprintf(out,
            "  -o, --output FILE where to write (default: stdout); written to a temporary\n"
            "                    file and renamed, so a failure leaves FILE untouched\n"
            "  --materials FILE  preset file (default: $SOAK_MATERIALS, else the shipped\n"
            "                    data/materials.json)\n\n"
            "examples:\n"
            "  soak export --target json -o soak_export.json\n"
            "  soak export --target povray -o povray/soak_materials.inc\n");
}

int soak_cmd_export(int argc, char **argv)
{
    const char *target_name = NULL, *output = NULL, *file = NULL;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return SOAK_EXIT_OK;
        } else if (cli_is(a, "--target")) {
            if (!(target_name = cli_value(CMD, argc, argv, &i))) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--output") || strcmp(a, "-o") == 0) {
            if (!(output = cli_value(CMD, argc, argv, &i))) return SOAK_EXIT_USAGE;
            if (!output[0]) {
                cli_error(CMD, "-o: empty file name");
                return SOAK_EXIT_USAGE;
            }
        } else if (cli_is(a, "--materials")) {
            if (!(file = cli_value(CMD, argc, argv, &i))) return SOAK_EXIT_USAGE;
        } else {
            cli_error(CMD, "unknown argument '%s' (see 'soak export --help')", a);
            return SOAK_EXIT_USAGE;
        }
    }
    if (!target_name) {
        cli_error(CMD, "--target is required (see 'soak export --help')");
        return SOAK_EXIT_USAGE;
    }
    const soak_export_target *target = soak_export_find_target(target_name);
    if (!target) {
        cli_error(CMD, "--target: unknown target '%s' (see 'soak export --help')", target_name);
        return SOAK_EXIT_USAGE;
    }
    char err[4352] = "";
    if (output && strcmp(output, "-") != 0) {
        const char *inputs[1] = {file ? file : soak_presets_default_path()};
        if (soak_io_check_output("-o", output, inputs, 1, err, sizeof err) != SOAK_OK) {
            cli_error(CMD, "%s (--materials or $SOAK_MATERIALS)", err);
            return SOAK_EXIT_USAGE;
        }
    }
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(file, &db, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    err[0] = '\0';
    st = soak_export_run(target, db, output, err, sizeof err);
    soak_presets_free(db);
    if (st != SOAK_OK) {
        cli_error(CMD, "--target %s: %s", target_name, err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    if (output && strcmp(output, "-") != 0) fprintf(stderr, "soak export: wrote %s\n", output);
    return SOAK_EXIT_OK;
}
