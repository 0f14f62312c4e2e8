/* soak eval: BRDF value of any model or fast path (soak/models.h). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "soak/ggx.h"
#include "soak/models.h"
#include "soak/porous.h"
#include "soak/ww.h"

static const char *const CMD = "eval";

typedef struct eval_args {
    const char *model;
    double theta_i, theta_o, phi, step;
    int csv;
} eval_args;

static int list_models(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    (void)cmd, (void)o, (void)text, (void)dst;
    size_t n;
    const soak_model *m = soak_models(&n);
    for (size_t k = 0; k < n; ++k) printf("%s\n", m[k].name);
    return CLI_OPT_STOP;
}

#define F(field) CLI_FIELD(eval_args, field)
static const cli_opt eval_opts[] = {
    {"--model", NULL, CLI_OPT_STRING, F(model), .meta = "MODEL", .help = "a model of --list (required)"},
    {"--theta-i", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 90, F(theta_i), .meta = "DEG", .help = "incidence, %R degrees"},
    {"--theta-o", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 90, F(theta_o), .meta = "DEG", .help = "exitance, %R degrees"},
    {"--phi", NULL, CLI_OPT_DOUBLE, .lo = -360, .hi = 360, F(phi), .meta = "DEG",
     .help = "azimuth of wo, %R degrees (default 180: the mirror side)"},
    {"--csv", NULL, CLI_OPT_FLAG, .flag = 1, F(csv), .help = "tabulate theta_i,theta_o,phi,f over theta in [0, 89]"},
    {"--step", NULL, CLI_OPT_DOUBLE, .lo = 0.1, .hi = 45, F(step), .meta = "DEG",
     .help = "--csv angle step, %R degrees (default 5)"},
    {"--list", NULL, CLI_OPT_ACTION, .parse = list_models, .help = "print the model names and exit"},
};
#undef F

/* The model's parameters, straight into soak_model_params; each model's
 * setup checks its own narrower ranges. */
#define P(field) CLI_FIELD(soak_model_params, field)
static const cli_opt param_opts[] = {
    {"--albedo", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, P(albedo), .meta = "A", .help = "%R [0.5]"},
    {"--ior", NULL, CLI_OPT_DOUBLE, .lo = SOAK_WW_N_CONDUCTOR_MIN, .hi = SOAK_WW_N_CONDUCTOR_MAX, P(ior), .meta = "N",
     .help = "%R [1.5]"},
    {"--k", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_GGX_K_MAX, P(k), .meta = "K", .help = "%R [0; > 0: a conductor]"},
    {"--roughness", NULL, CLI_OPT_DOUBLE, .lo = SOAK_GGX_ALPHA_MIN, .hi = SOAK_GGX_ALPHA_MAX, P(roughness),
     .meta = "ALPHA", .help = "%R [0.3]"},
    {"--film-ior", NULL, CLI_OPT_DOUBLE, .lo = SOAK_WW_N_WATER_MIN, .hi = SOAK_WW_N_WATER_MAX, P(n_film), .meta = "N",
     .help = "%R [1.333]"},
    {"--absorption", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_WW_ABSORPTION_MAX, P(absorption), .meta = "1/m",
     .help = "%R [0.35]"},
    {"--thickness", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_WW_THICKNESS_MAX, P(thickness), .meta = "m",
     .help = "%R [1e-3]"},
    {"--porosity", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, P(porosity), .meta = "P", .help = "%R [0.3]"},
    {"--sp", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_POROUS_SP_MAX, P(sp), .meta = "S", .help = "%R [2]"},
    {"--fill", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, P(fill), .meta = "F", .help = "%R [1]"},
    {"--ks", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, P(ks), .meta = "KS", .help = "%R [0.05]"},
    {"--ks-water", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_POROUS_KS_WATER_MAX, P(ks_water), .meta = "KW",
     .help = "%R [0.02]"},
};
#undef P

static void usage(FILE *out)
{
    size_t n;
    const soak_model *m = soak_models(&n);
    fprintf(out,
            "usage: soak eval --model MODEL [parameters] --theta-i DEG --theta-o DEG [--phi DEG]\n"
            "       soak eval --model MODEL [parameters] --csv [--step DEG] [--phi DEG]\n"
            "       soak eval --list\n\n"
            "Evaluates the BRDF f(wi, wo) in 1/sr (without the cosine). wi = (theta-i, azimuth 0),\n"
            "wo = (theta-o, azimuth phi); phi = 180 is the plane of incidence on the mirror side.\n"
            "--csv prints theta_i,theta_o,phi,f over theta in [0, 89] with --step (default 5).\n\n"
            "options:\n");
    const cli_opt_table opts[] = {CLI_TABLE(eval_opts, NULL)}, params[] = {CLI_TABLE(param_opts, NULL)};
    cli_opts_help(out, opts, 1);
    fprintf(out, "\nparameters (range [default]):\n");
    cli_opts_help(out, params, 1);
    fprintf(out, "\nmodels:\n");
    for (size_t i = 0; i < n; ++i)
        fprintf(out, "  %-15s %s%s%s\n", m[i].name, m[i].summary, m[i].exact ? "; fast path of " : "",
                m[i].exact ? m[i].exact : "");
    fprintf(out, "\nexample:\n  soak eval --model ww --roughness 0.2 --theta-i 30 --theta-o 30 --phi 180\n");
}

/* Returns -1 with the model set up in ctx, else the exit code. */
static int parse_args(int argc, char **argv, eval_args *a, const soak_model **m, soak_model_ctx *ctx)
{
    soak_model_params p;
    soak_model_params_default(&p);
    *a = (eval_args){.theta_i = -1, .theta_o = -1, .phi = 180, .step = 5};
    const cli_spec spec = {CMD, "option", "'soak eval --help'", usage, NULL, NULL};
    const cli_opt_table tables[] = {CLI_TABLE(param_opts, &p), CLI_TABLE(eval_opts, a)};
    int rc = cli_opts_parse(&spec, tables, 2, argc, argv);
    if (rc >= 0) return rc;
    if (!a->model) {
        cli_error(CMD, "--model is required (see 'soak eval --list')");
        return SOAK_EXIT_USAGE;
    }
    if (!(*m = soak_model_find(a->model))) {
        cli_error(CMD, "--model: unknown model '%s' (see 'soak eval --list')", a->model);
        return SOAK_EXIT_USAGE;
    }
    if (!a->csv && (a->theta_i < 0 || a->theta_o < 0)) {
        cli_error(CMD, "%s is required (or use --csv)", a->theta_i < 0 ? "--theta-i" : "--theta-o");
        return SOAK_EXIT_USAGE;
    }
    soak_status st = (*m)->setup(&p, ctx);
    if (st != SOAK_OK) {
        cli_error(CMD, "model '%s' rejects these parameters: %s", (*m)->name, soak_status_str(st));
        return SOAK_EXIT_USAGE;
    }
    return -1;
}

static soak_status eval_at(const soak_model *m, const soak_model_ctx *ctx, double ti, double to, double phi, double *f)
{
    const double deg = SOAK_PI / 180.0;
    return soak_model_eval(m, ctx, soak_v3_polar(ti * deg, 0), soak_v3_polar(to * deg, phi * deg), f);
}

static int print_csv(const eval_args *a, const soak_model *m, const soak_model_ctx *ctx)
{
    printf("theta_i,theta_o,phi,f\n");
    for (double ti = 0; ti < 89.0001; ti += a->step)
        for (double to = 0; to < 89.0001; to += a->step) {
            double f;
            soak_status st = eval_at(m, ctx, ti, to, a->phi, &f);
            if (st != SOAK_OK) {
                cli_error(CMD, "evaluation failed at theta_i %g theta_o %g: %s", ti, to, soak_status_str(st));
                return SOAK_EXIT_FAIL;
            }
            printf("%g,%g,%g,%.10g\n", ti, to, a->phi, f);
        }
    return SOAK_EXIT_OK;
}

int soak_cmd_eval(int argc, char **argv)
{
    eval_args a;
    const soak_model *m = NULL;
    soak_model_ctx ctx;
    int rc = parse_args(argc, argv, &a, &m, &ctx);
    if (rc >= 0) return rc;
    if (a.csv) return print_csv(&a, m, &ctx);
    double f;
    soak_status st = eval_at(m, &ctx, a.theta_i, a.theta_o, a.phi, &f);
    if (st != SOAK_OK) {
        cli_error(CMD, "evaluation failed: %s", soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    printf("# model %s theta_i %g theta_o %g phi %g: f (1/sr)\n%.10g\n", m->name, a.theta_i, a.theta_o, a.phi, f);
    return SOAK_EXIT_OK;
}
