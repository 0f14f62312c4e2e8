/* soak materials: list the presets as a table, or export them (and their
 * wetness tables) as JSON for the POV-Ray and Blender front ends. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "soak/preset.h"
#include "soak/wetness.h"

static const char *CMD = "materials";

typedef struct materials_args {
    const char *liquid, *file;
    int json;
    long table;
} materials_args;

#define F(field) CLI_FIELD(materials_args, field)
static const cli_opt materials_opts[] = {
    {"--json", NULL, CLI_OPT_FLAG, .flag = 1, F(json),
     .help = "print every preset and liquid with all fields, sources\n"
             "and derived sigma_s/sigma_a (1/mm) as JSON on stdout"},
    {"--table", NULL, CLI_OPT_INT, .ilo = 2, .ihi = SOAK_WET_TABLE_MAX, F(table), .meta = "N",
     .help = "add N rows (N in %R) at wetness i/(N-1) per preset: the\n"
             "parameter table front ends interpolate (in the JSON with\n"
             "--json, else printed as text); the curves have a kink\n"
             "where the pores saturate, so use 17 rows or more"},
    {"--liquid", NULL, CLI_OPT_STRING, F(liquid), .meta = "NAME", .help = "liquid for the wet values (default water)"},
    {"--materials", NULL, CLI_OPT_STRING, F(file), .meta = "FILE",
     .help = "preset file (default: $SOAK_MATERIALS, else the shipped\ndata/materials.json)"},
};
#undef F

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak materials [--json] [--table N] [--liquid NAME] [--materials FILE]\n\n"
            "Lists the material presets: kind, porosity, index, dry albedo and the\n"
            "albedo when fully wet (wetness 1, steady state) with the chosen liquid,\n"
            "the wet/dry ratio of the total reflectance (film specular included), and\n"
            "for presets calibrated against a published measurement the measured\n"
            "ratio +- its spread beside the model's ratio at the measured sample's dry\n"
            "albedo (docs/calibration.md; the measurement is for water).\n\n"
            "options:\n");
    const cli_opt_table tables[] = {CLI_TABLE(materials_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out, "\nexamples:\n"
                 "  soak materials\n"
                 "  soak materials --json --table 17 > presets.json\n");
}

static void print_rgb(soak_rgb c) { printf("%6.3f %6.3f %6.3f", c.r, c.g, c.b); }

/* The chain's wet/dry ratio at the measured sample's grey dry albedo (the
 * comparison of docs/calibration.md and tests/c/materials/test_calibration.c). */
static soak_status measured_model_ratio(const soak_preset *p, const soak_liquid *liq, double *ratio)
{
    soak_preset q = *p;
    double dry = p->measured_dry_albedo;
    q.albedo = soak_rgb3(dry, dry, dry);
    soak_status st = soak_preset_derive(&q);
    soak_wet_input in = soak_wet_input_steady(&q, p->measured_wetness);
    soak_wet_params o;
    if (st == SOAK_OK) st = soak_wetness_eval(&q, liq, &in, &o);
    if (st == SOAK_OK) *ratio = (p->measured_total ? o.albedo_total.g : o.albedo.g) / dry;
    return st;
}

static double mean_ratio(soak_rgb wet, soak_rgb dry)
{
    double s = 0.0;
    int n = 0;
    for (int c = 0; c < 3; ++c)
        if (soak_rgb_at(dry, c) > 0.0) {
            s += soak_rgb_at(wet, c) / soak_rgb_at(dry, c);
            ++n;
        }
    return n ? s / n : 0.0;
}

static int print_summary(const soak_preset_db *db, const soak_liquid *liq)
{
    printf("presets from %s; wet = wetness 1, steady state, liquid %s\n\n", soak_presets_path(db), liq->name);
    printf("%-10s %-20s %8s %6s  %-20s  %-20s  %-17s  %7s  %s\n", "name", "kind", "porosity", "ior",
           "dry albedo R G B", "wet albedo R G B", "mean cos dry->wet", "wet/dry", "measured wet/dry | model at sample");
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        soak_wet_input in = soak_wet_input_steady(p, 1.0);
        soak_wet_params wet;
        soak_status st = soak_wetness_eval(p, liq, &in, &wet);
        if (st != SOAK_OK) {
            cli_error(CMD, "%s: wetness mapping failed: %s", p->name, soak_status_str(st));
            return SOAK_EXIT_FAIL;
        }
        printf("%-10s %-20s ", p->name, soak_material_kind_name(p->kind));
        if (soak_material_kind_porous(p->kind))
            printf("%8.3f ", p->porosity);
        else
            printf("%8s ", "-");
        if (p->kind == SOAK_KIND_CONDUCTOR)
            printf("%6s  ", "n,k");
        else
            printf("%6.3f  ", p->ior);
        print_rgb(p->albedo);
        printf("  ");
        print_rgb(wet.albedo);
        if (p->kind == SOAK_KIND_CONDUCTOR)
            printf("  %-17s", "-");
        else
            printf("  %.3f -> %.3f    ", soak_hg2_mean_cosine(&p->phase_dry), wet.mean_cosine);
        printf("  %7.3f  ", mean_ratio(wet.albedo_total, p->albedo));
        double model = 0.0;
        if (!p->has_measured) {
            printf("-\n");
        } else if ((st = measured_model_ratio(p, liq, &model)) != SOAK_OK) {
            cli_error(CMD, "%s: wetness mapping at the measured dry albedo failed: %s", p->name, soak_status_str(st));
            return SOAK_EXIT_FAIL;
        } else {
            printf("%.3f +- %.3f | %.3f (dry %.3f)\n", p->measured_ratio, p->measured_spread, model,
                   p->measured_dry_albedo);
        }
    }
    printf("\nliquids:");
    for (int i = 0; i < soak_presets_liquid_count(db); ++i) printf(" %s", soak_presets_liquid_at(db, i)->name);
    printf("\n");
    return SOAK_EXIT_OK;
}

static int print_tables(const soak_preset_db *db, const soak_liquid *liq, int n)
{
    soak_wet_params *rows = malloc((size_t)n * sizeof *rows);
    if (!rows) {
        cli_error(CMD, "out of memory for %d table rows", n);
        return SOAK_EXIT_FAIL;
    }
    for (int i = 0; i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        soak_status st = soak_wetness_table(p, liq, n, -1.0, rows);
        if (st != SOAK_OK) {
            cli_error(CMD, "%s: wetness table failed: %s", p->name, soak_status_str(st));
            free(rows);
            return SOAK_EXIT_FAIL;
        }
        printf("%s (%s), liquid %s\n", p->name, p->display_name, liq->name);
        printf("  %7s %6s %8s  %-20s  %-20s %9s %8s\n", "wetness", "fill", "coverage", "albedo R G B",
               "albedo_total R G B", "ggx_alpha", "mean_cos");
        for (int r = 0; r < n; ++r) {
            printf("  %7.4f %6.3f %8.3f  ", rows[r].wetness, rows[r].fill, rows[r].film_coverage);
            print_rgb(rows[r].albedo);
            printf("  ");
            print_rgb(rows[r].albedo_total);
            printf(" %9.4f %8.4f\n", rows[r].ggx_alpha, rows[r].mean_cosine);
        }
        printf("\n");
    }
    free(rows);
    return SOAK_EXIT_OK;
}

static void list_liquids(const soak_preset_db *db)
{
    fprintf(stderr, "known liquids:");
    for (int i = 0; i < soak_presets_liquid_count(db); ++i) fprintf(stderr, " %s", soak_presets_liquid_at(db, i)->name);
    fprintf(stderr, "\n");
}

static int print_json(const soak_preset_db *db, const materials_args *a)
{
    char *text = NULL;
    soak_status st = soak_wetness_export_json(db, a->liquid, (int)a->table, &text);
    if (st != SOAK_OK) {
        cli_error(CMD, "JSON export failed: %s", soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    fputs(text, stdout);
    fputc('\n', stdout);
    free(text);
    return SOAK_EXIT_OK;
}

int soak_cmd_materials(int argc, char **argv)
{
    materials_args a = {.liquid = "water"};
    const cli_spec spec = {CMD, "argument", "'soak materials --help'", usage, NULL, NULL};
    const cli_opt_table tables[] = {CLI_TABLE(materials_opts, &a)};
    int rc = cli_opts_parse(&spec, tables, 1, argc, argv);
    if (rc >= 0) return rc;
    char err[1024];
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(a.file, &db, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    const soak_liquid *liq = soak_presets_find_liquid(db, a.liquid);
    if (!liq) {
        cli_error(CMD, "--liquid: unknown liquid '%s'", a.liquid);
        list_liquids(db);
        rc = SOAK_EXIT_USAGE;
    } else if (a.json) {
        rc = print_json(db, &a);
    } else {
        rc = a.table ? print_tables(db, liq, (int)a.table) : print_summary(db, liq);
    }
    soak_presets_free(db);
    if (rc == SOAK_EXIT_OK && fflush(stdout) != 0) {
        cli_error(CMD, "writing to stdout failed");
        rc = SOAK_EXIT_FAIL;
    }
    return rc;
}
