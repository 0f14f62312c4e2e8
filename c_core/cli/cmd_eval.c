/* soak eval: BRDF value of any model or fast path (soak/models.h). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "soak/models.h"
#include "soak/porous.h"

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
            "parameters (defaults in brackets):\n"
            "  --albedo A [0.5]  --ior N [1.5]  --k K [0, >0 = conductor]  --roughness ALPHA [0.3]\n"
            "  --film-ior N [1.333]  --absorption 1/m [0.35]  --thickness m [1e-3]\n"
            "  --porosity P [0.3]  --sp S [2]  --fill F [1]  --ks KS [0.05]  --ks-water KW [0.02, at most 0.5]\n\n"
            "models:\n");
    for (size_t i = 0; i < n; ++i)
        fprintf(out, "  %-15s %s%s%s\n", m[i].name, m[i].summary, m[i].exact ? "; fast path of " : "",
                m[i].exact ? m[i].exact : "");
    fprintf(out, "\nexample:\n  soak eval --model ww --roughness 0.2 --theta-i 30 --theta-o 30 --phi 180\n");
}

typedef struct {
    const char *opt;
    double lo, hi;
    size_t offset;
} param_opt;

#define P(opt, lo, hi, field) {opt, lo, hi, offsetof(soak_model_params, field)}
static const param_opt params[] = {
    P("--albedo", 0, 1, albedo),       P("--ior", 0.01, 100, ior),          P("--k", 0, 1000, k),
    P("--roughness", 1e-4, 1, roughness), P("--film-ior", 1, 3, n_film),    P("--absorption", 0, 1e6, absorption),
    P("--thickness", 0, 1e3, thickness), P("--porosity", 0, 1, porosity),  P("--sp", 0, 50, sp),
    P("--fill", 0, 1, fill),           P("--ks", 0, 1, ks),                 P("--ks-water", 0, SOAK_POROUS_KS_WATER_MAX, ks_water),
};
#undef P

int soak_cmd_eval(int argc, char **argv)
{
    const char *cmd = "eval", *model_name = NULL;
    soak_model_params p;
    soak_model_params_default(&p);
    double ti = -1, to = -1, phi = 180, step = 5;
    int csv = 0;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return SOAK_EXIT_OK;
        }
        if (!strcmp(a, "--list")) {
            size_t n;
            const soak_model *m = soak_models(&n);
            for (size_t k = 0; k < n; ++k) printf("%s\n", m[k].name);
            return SOAK_EXIT_OK;
        }
        if (!strcmp(a, "--csv")) {
            csv = 1;
            continue;
        }
        int matched = 0;
        for (size_t k = 0; k < sizeof params / sizeof params[0]; ++k) {
            if (!cli_is(a, params[k].opt)) continue;
            matched = 1;
            if (!(v = cli_value(cmd, argc, argv, &i)) ||
                !cli_parse_double(cmd, params[k].opt, v, params[k].lo, params[k].hi,
                                  (double *)((char *)&p + params[k].offset)))
                return SOAK_EXIT_USAGE;
        }
        if (matched) continue;
        if (cli_is(a, "--model")) {
            if (!(model_name = cli_value(cmd, argc, argv, &i))) return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--theta-i")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_double(cmd, "--theta-i", v, 0, 90, &ti))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--theta-o")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_double(cmd, "--theta-o", v, 0, 90, &to))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--phi")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_double(cmd, "--phi", v, -360, 360, &phi))
                return SOAK_EXIT_USAGE;
        } else if (cli_is(a, "--step")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) || !cli_parse_double(cmd, "--step", v, 0.1, 45, &step))
                return SOAK_EXIT_USAGE;
        } else {
            cli_error(cmd, "unknown option '%s' (see 'soak eval --help')", a);
            return SOAK_EXIT_USAGE;
        }
    }
    if (!model_name) {
        cli_error(cmd, "--model is required (see 'soak eval --list')");
        return SOAK_EXIT_USAGE;
    }
    const soak_model *m = soak_model_find(model_name);
    if (!m) {
        cli_error(cmd, "--model: unknown model '%s' (see 'soak eval --list')", model_name);
        return SOAK_EXIT_USAGE;
    }
    if (!csv && (ti < 0 || to < 0)) {
        cli_error(cmd, "%s is required (or use --csv)", ti < 0 ? "--theta-i" : "--theta-o");
        return SOAK_EXIT_USAGE;
    }
    soak_model_ctx ctx;
    soak_status st = m->setup(&p, &ctx);
    if (st != SOAK_OK) {
        cli_error(cmd, "model '%s' rejects these parameters: %s", m->name, soak_status_str(st));
        return SOAK_EXIT_USAGE;
    }
    const double deg = SOAK_PI / 180.0;
    if (!csv) {
        double f;
        st = soak_model_eval(m, &ctx, soak_v3_polar(ti * deg, 0), soak_v3_polar(to * deg, phi * deg), &f);
        if (st != SOAK_OK) {
            cli_error(cmd, "evaluation failed: %s", soak_status_str(st));
            return SOAK_EXIT_FAIL;
        }
        printf("# model %s theta_i %g theta_o %g phi %g: f (1/sr)\n%.10g\n", m->name, ti, to, phi, f);
        return SOAK_EXIT_OK;
    }
    printf("theta_i,theta_o,phi,f\n");
    for (double a = 0; a < 89.0001; a += step)
        for (double b = 0; b < 89.0001; b += step) {
            double f;
            st = soak_model_eval(m, &ctx, soak_v3_polar(a * deg, 0), soak_v3_polar(b * deg, phi * deg), &f);
            if (st != SOAK_OK) {
                cli_error(cmd, "evaluation failed at theta_i %g theta_o %g: %s", a, b, soak_status_str(st));
                return SOAK_EXIT_FAIL;
            }
            printf("%g,%g,%g,%.10g\n", a, b, phi, f);
        }
    return SOAK_EXIT_OK;
}
