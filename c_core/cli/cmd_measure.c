/* soak measure: virtual gonio-reflectometer (soak/measure.h). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "soak/film.h"
#include "soak/fresnel.h"
#include "soak/hg.h"
#include "soak/measure.h"
#include "soak/preset.h"
#include "soak/wetness.h"

static const char *CMD = "measure";

typedef struct measure_args {
    soak_measure_setup setup;
    int have_config, have_ior, have_base, have_albedo, have_tau, have_g, have_g2;
    int have_g1, have_w;
    const char *material;
    const char *liquid;
    int have_wetness, have_channel, have_base_alpha, have_coat;
    double wetness;
    int channel;
} measure_args;

/* A per-path cap on tracking steps, not a limit of the library's (>= 1). */
#define MEASURE_MAX_EVENTS 1000000000000L

static int read_config(const char *cmd, const cli_opt *o, const char *v, void *dst)
{
    (void)o;
    soak_measure_config *c = &((measure_args *)dst)->setup.config;
    if (strcmp(v, "film") == 0) *c = SOAK_MEASURE_FILM;
    else if (strcmp(v, "halfspace") == 0) *c = SOAK_MEASURE_HALFSPACE;
    else if (strcmp(v, "slab") == 0) *c = SOAK_MEASURE_SLAB;
    else if (strcmp(v, "coated") == 0) *c = SOAK_MEASURE_COATED;
    else {
        cli_error(cmd, "--config: unknown configuration '%s' (expected film, halfspace, slab or coated)", v);
        return 0;
    }
    return 1;
}

static int read_incidence(const char *cmd, const cli_opt *o, const char *v, void *dst)
{
    (void)o;
    soak_measure_setup *s = &((measure_args *)dst)->setup;
    if (strcmp(v, "normal") == 0) {
        s->diffuse_incidence = 0;
        s->cos_incidence = 1.0;
        return 1;
    }
    if (strcmp(v, "diffuse") == 0) {
        s->diffuse_incidence = 1;
        return 1;
    }
    double deg;
    if (!cli_parse_double(cmd, "--incidence", v, 0.0, 90.0, &deg)) {
        cli_error(cmd, "--incidence: use normal, diffuse or an angle in degrees [0, 90)");
        return 0;
    }
    if (deg >= 90.0) {
        cli_error(cmd, "--incidence: %s degrees is grazing; use an angle below 90", v);
        return 0;
    }
    s->diffuse_incidence = 0;
    s->cos_incidence = cos(deg * SOAK_PI / 180.0);
    return 1;
}

static int read_tau(const char *cmd, const cli_opt *o, const char *v, void *dst)
{
    double *tau = &((measure_args *)dst)->setup.tau;
    if (!cli_parse_double(cmd, o->name, v, o->lo, o->hi, tau)) return 0;
    if (!(*tau > 0.0)) {
        cli_error(cmd, "--tau: the optical thickness must be > 0, got '%s'", v);
        return 0;
    }
    return 1;
}

static const cli_choice quantities[] = {
    {"R", SOAK_MEASURE_R, 0}, {"T", SOAK_MEASURE_T, 0}, {"r", SOAK_MEASURE_R, 1}, {"t", SOAK_MEASURE_T, 1},
    {NULL, 0, 0}};
static const cli_choice channels[] = {{"r", 0, 0}, {"g", 1, 0}, {"b", 2, 0}, {NULL, 0, 0}};

#define F(field) CLI_FIELD(measure_args, field)
#define SEEN(field) CLI_SEEN(measure_args, field)
static const cli_opt measure_opts[] = {
    {"", NULL, CLI_OPT_HEADING, .help = "configuration:"},
    {"--config", NULL, CLI_OPT_CUSTOM, .parse = read_config, SEEN(have_config), .meta = "NAME",
     .help = "film: smooth liquid film over a Lambertian base;\n"
             "halfspace: semi-infinite scattering medium;\n"
             "slab: scattering slab of optical thickness --tau;\n"
             "coated: rough dielectric interface (--coat-*) over a Lambertian\n"
             "base, under a film when --ior > 1 (the renderer's preset surface)"},
    {"--incidence", NULL, CLI_OPT_CUSTOM, .parse = read_incidence, .meta = "I",
     .help = "normal (default), diffuse, or an angle in degrees [0, 90)"},
    {"--quantity", NULL, CLI_OPT_CHOICE, .choices = quantities, F(setup.quantity), .meta = "R|T",
     .help = "reflectance (default) or transmittance (slab only)"},
    {"--ior", NULL, CLI_OPT_DOUBLE, .lo = SOAK_MEASURE_MIN_IOR, .hi = SOAK_MEASURE_MAX_IOR, F(setup.ior),
     SEEN(have_ior), .meta = "N",
     .help = "film / medium index relative to air, %R\n(default 1.333 for film, 1 = index-matched otherwise)"},
    {"", NULL, CLI_OPT_HEADING, .help = "film:"},
    {"--base-albedo", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(setup.base_albedo), SEEN(have_base), .meta = "A",
     .help = "albedo of the Lambertian base, %R (required)"},
    {"--film-alpha", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_FILM_MAX_ALPHA, F(setup.film_alpha),
     SEEN(have_base_alpha), .meta = "A", .help = "absorption coefficient of the liquid, %R 1/m (default 0)"},
    {"--film-thickness", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_FILM_MAX_THICKNESS, F(setup.film_thickness),
     SEEN(have_base_alpha), .meta = "D", .help = "film thickness, %R m (default 0: no absorption)"},
    {"", NULL, CLI_OPT_HEADING, .help = "coated (with --base-albedo and the film's options):"},
    {"--coat-ior", NULL, CLI_OPT_DOUBLE, .lo = SOAK_MEASURE_MIN_IOR, .hi = SOAK_MEASURE_MAX_IOR, F(setup.coat_ior),
     SEEN(have_coat), .meta = "N", .help = "index of the interface relative to air, %R (default 1.5)"},
    {"--coat-alpha", NULL, CLI_OPT_DOUBLE, .lo = 1e-4, .hi = 1, F(setup.coat_alpha), SEEN(have_coat), .meta = "A",
     .help = "its GGX width, %R (default 0.1)"},
    {"--coat-weight", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(setup.coat_weight), SEEN(have_coat), .meta = "KS",
     .help = "its specular weight (1 - porosity), %R (default 1)"},
    {"", NULL, CLI_OPT_HEADING, .help = "halfspace, slab (lengths in mean free paths):"},
    {"--albedo", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(setup.albedo), SEEN(have_albedo), .meta = "W",
     .help = "single-scattering albedo, %R (required)"},
    {"--g", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_HG_G_MAX, .hi = SOAK_HG_G_MAX, F(setup.phase.g1), SEEN(have_g),
     .meta = "G", .help = "single Henyey-Greenstein lobe (default 0: isotropic)"},
    {"--g1", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_HG_G_MAX, .hi = SOAK_HG_G_MAX, F(setup.phase.g1), SEEN(have_g1),
     .meta = "G", .help = "two-term HG (Jensen et al. 1999, Eq. 5): --g1, --g2 and --w"},
    {"--g2", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_HG_G_MAX, .hi = SOAK_HG_G_MAX, F(setup.phase.g2), SEEN(have_g2),
     .meta = "G", .help = "the second lobe"},
    {"--w", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(setup.phase.w), SEEN(have_w), .meta = "W",
     .help = "weight of the g1 lobe"},
    {"--tau", NULL, CLI_OPT_CUSTOM, .parse = read_tau, SEEN(have_tau), .lo = 0, .hi = SOAK_MEASURE_MAX_TAU,
     .meta = "T", .help = "optical thickness of the slab, %R and > 0 (slab, required)"},
    {"", NULL, CLI_OPT_HEADING, .help = "run:"},
    {"--paths", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_MEASURE_MAX_PATHS, F(setup.paths), .meta = "N",
     .help = "photons traced, %R (default 1000000)"},
    {"--seed", NULL, CLI_OPT_INT, .ilo = 0, .ihi = INT64_MAX, F(setup.seed), .meta = "S",
     .help = "RNG seed (default 1); results depend only on the seed"},
    {"--threads", NULL, CLI_OPT_INT, .ilo = 1, .ihi = SOAK_MEASURE_MAX_THREADS, F(setup.threads), .meta = "N",
     .help = "worker threads, %R (default: all online cores)"},
    {"--max-events", NULL, CLI_OPT_INT, .ilo = 1, .ihi = MEASURE_MAX_EVENTS, F(setup.max_events), .meta = "N",
     .help = "per-path cap on tracking steps (default 1000000);\ncapped paths are counted and reported"},
    {"--no-roulette", NULL, CLI_OPT_FLAG, .flag = 0, F(setup.roulette),
     .help = "disable Russian roulette (slower; for checks)"},
    {"", NULL, CLI_OPT_HEADING, .help = "material presets (soak materials; replace the raw medium/film parameters):"},
    {"--material", NULL, CLI_OPT_STRING, F(material), .meta = "NAME", .help = "preset name; needs --wetness"},
    {"--wetness", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(wetness), SEEN(have_wetness), .meta = "W",
     .help = "wetness in %R, steady state (soak/wetness.h)"},
    {"--channel", NULL, CLI_OPT_CHOICE, .choices = channels, F(channel), SEEN(have_channel), .meta = "r|g|b",
     .help = "colour channel to trace (default g)"},
    {"--liquid", NULL, CLI_OPT_STRING, F(liquid), .meta = "NAME", .help = "liquid (default water)"},
};
#undef F
#undef SEEN

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak measure --config film|halfspace|slab|coated [options]\n\n"
            "Traces photons through a canonical plane-parallel configuration and prints\n"
            "its reflectance (or a slab's transmittance). The last line of the output is\n"
            "'value ± standard error'.\n\n");
    const cli_opt_table tables[] = {CLI_TABLE(measure_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out,
            "\nA preset sets the medium: halfspace (the default for a preset): the wet medium's\n"
            "omega and phase, index-matched unless --ior; slab: a thin sheet, tau = sigma_t *\n"
            "sheet thickness; film: the film over the wet subsurface albedo; coated: the\n"
            "material's rough interface (its index, the chain's GGX width and weight\n"
            "1 - porosity) over the subsurface albedo, under the film where one lies (the\n"
            "surface soak render shades). The model's own value is printed alongside.\n\n"
            "examples:\n"
            "  soak measure --config film --base-albedo 0.5 --ior 1.33 --incidence normal --paths 200000\n"
            "  soak measure --config halfspace --albedo 0.9 --incidence 60\n"
            "  soak measure --config slab --tau 2 --albedo 0.9 --g 0.5 --quantity T\n"
            "  soak measure --config coated --base-albedo 0.4 --coat-ior 1.5 --coat-alpha 0.25 --incidence 60\n"
            "  soak measure --material sand --wetness 1 --incidence diffuse --channel r\n");
}

/* Returns -1 to continue, or an exit code. */
static int parse_args(int argc, char **argv, measure_args *a)
{
    memset(a, 0, sizeof *a);
    soak_measure_setup_default(&a->setup);
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    a->setup.threads = cores >= 1 && cores <= SOAK_MEASURE_MAX_THREADS ? (int)cores : 1;
    a->setup.phase.w = 1.0;
    const cli_spec spec = {CMD, "option", "'soak measure --help'", usage, NULL, NULL};
    const cli_opt_table tables[] = {CLI_TABLE(measure_opts, a)};
    int rc = cli_opts_parse(&spec, tables, 1, argc, argv);
    if (rc >= 0) return rc;
    if (a->have_g) { /* one lobe; with --g1/--g2/--w it is refused below */
        a->setup.phase.g2 = a->setup.phase.g1;
        a->setup.phase.w = 1.0;
    }
    return -1;
}

/* --material mode: the preset replaces the medium and film options. */
static int check_preset_mode(measure_args *a)
{
    soak_measure_setup *s = &a->setup;
    if (!a->material || !a->have_wetness) {
        cli_error(CMD, "%s: a preset needs both --material NAME and --wetness W",
                  a->material ? "--wetness" : "--material");
        return 0;
    }
    if (a->have_albedo || a->have_tau || a->have_g || a->have_g1 || a->have_g2 || a->have_w || a->have_base ||
        a->have_base_alpha || a->have_coat) {
        cli_error(CMD, "--material: replaces --albedo/--g*/--tau/--base-albedo/--film-*/--coat-*; give one or the other");
        return 0;
    }
    if (!a->have_config) s->config = SOAK_MEASURE_HALFSPACE;
    if (s->quantity == SOAK_MEASURE_T && s->config != SOAK_MEASURE_SLAB) {
        cli_error(CMD, "--quantity T: only a slab transmits");
        return 0;
    }
    return 1; /* the rest is checked once the preset is loaded */
}

/* The options each configuration needs and refuses. */
static int check_config(measure_args *a)
{
    soak_measure_setup *s = &a->setup;
    if (s->config == SOAK_MEASURE_FILM || s->config == SOAK_MEASURE_COATED) {
        if (!a->have_base) {
            cli_error(CMD, "--base-albedo is required for --config %s", s->config == SOAK_MEASURE_FILM ? "film" : "coated");
            return 0;
        }
        if (!a->have_ior) s->ior = s->config == SOAK_MEASURE_FILM ? SOAK_WATER_IOR : 1.0;
        if (a->have_albedo || a->have_tau || a->have_g || a->have_g1) {
            cli_error(CMD, "--albedo/--tau/--g*: not used by --config film (it has no scattering medium)");
            return 0;
        }
        return 1;
    }
    if (!a->have_albedo) {
        cli_error(CMD, "--albedo is required for --config %s", s->config == SOAK_MEASURE_SLAB ? "slab" : "halfspace");
        return 0;
    }
    if (a->have_coat) {
        cli_error(CMD, "--coat-*: only --config coated has an interface");
        return 0;
    }
    if (s->config == SOAK_MEASURE_SLAB && !a->have_tau) {
        cli_error(CMD, "--tau is required for --config slab");
        return 0;
    }
    if (s->config == SOAK_MEASURE_HALFSPACE && a->have_tau) {
        cli_error(CMD, "--tau: a half-space has no thickness (use --config slab)");
        return 0;
    }
    return 1;
}

static int check_combination(measure_args *a)
{
    soak_measure_setup *s = &a->setup;
    if (a->material || a->have_wetness || a->have_channel || a->liquid) return check_preset_mode(a);
    if (!a->have_config) {
        cli_error(CMD, "--config is required (film, halfspace, slab or coated)");
        return 0;
    }
    if (a->have_g && (a->have_g1 || a->have_g2 || a->have_w)) {
        cli_error(CMD, "--g: give either --g or --g1/--g2/--w, not both");
        return 0;
    }
    if ((a->have_g1 || a->have_g2 || a->have_w) && !(a->have_g1 && a->have_g2 && a->have_w)) {
        cli_error(CMD, "--g1/--g2/--w: the two-term phase function needs all three");
        return 0;
    }
    if (!check_config(a)) return 0;
    if (s->quantity == SOAK_MEASURE_T && s->config != SOAK_MEASURE_SLAB) {
        cli_error(CMD, "--quantity T: only a slab transmits");
        return 0;
    }
    return 1;
}

/* The preset and liquid of --material/--liquid at --wetness (steady state).
 * Returns -1 with *db loaded, else the exit code with nothing to free. */
static int wet_preset(const measure_args *a, soak_preset_db **db, const soak_preset **p, soak_wet_params *wp)
{
    char err[512] = "";
    soak_status st = soak_presets_load(NULL, db, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "--material: cannot load the presets: %s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    int rc = -1;
    const char *liquid_name = a->liquid ? a->liquid : "water";
    const soak_liquid *liq = soak_presets_find_liquid(*db, liquid_name);
    if (!(*p = soak_presets_find(*db, a->material))) {
        cli_error(CMD, "--material: no preset named '%s' in %s (see 'soak materials')", a->material,
                  soak_presets_path(*db));
        rc = SOAK_EXIT_USAGE;
    } else if (!liq) {
        cli_error(CMD, "--liquid: no liquid named '%s' in %s", liquid_name, soak_presets_path(*db));
        rc = SOAK_EXIT_USAGE;
    } else if ((*p)->kind == SOAK_KIND_CONDUCTOR) {
        cli_error(CMD, "--material: '%s' is a conductor: it has neither a scattering medium nor a Lambertian base",
                  a->material);
        rc = SOAK_EXIT_USAGE;
    } else {
        soak_wet_input in = soak_wet_input_steady(*p, a->wetness);
        if ((st = soak_wetness_eval(*p, liq, &in, wp)) != SOAK_OK) {
            cli_error(CMD, "--material %s --wetness %g: wetness model failed: %s", a->material, a->wetness,
                      soak_status_str(st));
            rc = SOAK_EXIT_FAIL;
        }
    }
    if (rc >= 0) soak_presets_free(*db);
    return rc;
}

/* The wet preset's channel c as the setup of the configuration; prints the
 * model's own value for comparison. Returns -1 or the exit code. */
static int preset_setup(measure_args *a, const soak_preset *p, const soak_wet_params *wp, int c)
{
    soak_measure_setup *s = &a->setup;
    int rc = -1;
    if (s->config == SOAK_MEASURE_COATED) {
        /* the chain's interface (wetness.h step 6); the film where one lies */
        s->coat_ior = p->ior;
        s->coat_alpha = wp->ggx_alpha;
        s->coat_weight = wp->specular_weight;
    }
    if (s->config == SOAK_MEASURE_FILM || s->config == SOAK_MEASURE_COATED) {
        s->base_albedo = soak_rgb_at(wp->albedo_subsurface, c);
        s->ior = s->config == SOAK_MEASURE_COATED && !wp->film ? 1.0 : wp->film_ior;
        s->film_alpha = soak_rgb_at(wp->film_absorption_per_m, c);
        s->film_thickness = wp->film_thickness_m;
        if (!(s->film_alpha <= SOAK_FILM_MAX_ALPHA && s->film_thickness <= SOAK_FILM_MAX_THICKNESS)) {
            cli_error(CMD, "--material: film parameters of '%s' out of the tracer's range", a->material);
            rc = SOAK_EXIT_USAGE;
        }
        printf("model: subsurface albedo %.6f; film albedo at full coverage %.6f (diffuse part, diffuse light)\n",
               s->base_albedo, soak_rgb_at(wp->albedo_film, c));
        return rc;
    }
    s->albedo = soak_rgb_at(wp->omega, c);
    s->phase = wp->phase;
    if (!a->have_ior) s->ior = 1.0;
    if (s->config == SOAK_MEASURE_SLAB) {
        s->tau = soak_rgb_at(p->sigma_t_per_m, c) * p->thickness_m;
        if (!(s->tau > 0.0 && s->tau <= SOAK_MEASURE_MAX_TAU)) {
            cli_error(CMD, "--config slab: preset '%s' is not a thin sheet (no finite thickness)", a->material);
            rc = SOAK_EXIT_USAGE;
        }
    }
    printf("model: subsurface albedo %.6f (van de Hulst, semi-infinite, index-matched, diffuse light)\n",
           soak_rgb_at(wp->albedo_subsurface, c));
    return rc;
}

/* Fills the setup from a preset at the given wetness (steady state) for one
 * colour channel. Returns an exit code, or -1 to go on. */
static int apply_material(measure_args *a)
{
    soak_preset_db *db = NULL;
    const soak_preset *p = NULL;
    soak_wet_params wp;
    int rc = wet_preset(a, &db, &p, &wp);
    if (rc >= 0) return rc;
    int c = a->have_channel ? a->channel : 1;
    const char *cname = c == 0 ? "r" : (c == 1 ? "g" : "b");
    printf("material: %s, wetness %g, liquid %s, channel %s (pore fill %.3f, film coverage %.3f)\n", p->name,
           a->wetness, a->liquid ? a->liquid : "water", cname, wp.fill, wp.film_coverage);
    rc = preset_setup(a, p, &wp, c);
    soak_presets_free(db);
    return rc;
}

static void on_progress(void *ctx, double fraction)
{
    cli_progress_update(ctx, fraction);
}

static const char *config_name(soak_measure_config c)
{
    return c == SOAK_MEASURE_FILM     ? "film"
           : c == SOAK_MEASURE_SLAB   ? "slab"
           : c == SOAK_MEASURE_COATED ? "coated"
                                      : "halfspace";
}

static void print_setup(const soak_measure_setup *s)
{
    printf("config: %s, ior %g", config_name(s->config), s->ior);
    if (s->config == SOAK_MEASURE_FILM || s->config == SOAK_MEASURE_COATED) {
        printf(", base albedo %g", s->base_albedo);
        if (s->config == SOAK_MEASURE_COATED)
            printf(", interface ior %g alpha %g weight %g", s->coat_ior, s->coat_alpha, s->coat_weight);
        if (s->film_alpha > 0.0 && s->film_thickness > 0.0)
            printf(", absorption %g 1/m over %g m", s->film_alpha, s->film_thickness);
    } else {
        printf(", albedo %g, HG g1 %g g2 %g w %g", s->albedo, s->phase.g1, s->phase.g2, s->phase.w);
        if (s->config == SOAK_MEASURE_SLAB) printf(", tau %g", s->tau);
    }
    printf("\n");
    if (s->diffuse_incidence)
        printf("incidence: diffuse\n");
    else
        printf("incidence: collimated, %.6g deg (cos %.6g)\n", acos(s->cos_incidence) * 180.0 / SOAK_PI,
               s->cos_incidence);
    printf("paths: %lld, seed %llu, threads %d, roulette %s, max events %ld\n", s->paths,
           (unsigned long long)s->seed, s->threads, s->roulette ? "on" : "off", s->max_events);
}

static void print_result(const soak_measure_setup *s, const soak_measure_result *r, double seconds)
{
    print_setup(s);
    printf("mean tracking steps per path: %.3f (%.2f s)\n", r->mean_events, seconds);
    printf("capped paths: %lld (unscored throughput per path %.3g)\n", r->capped, r->capped_weight);
    printf("reflectance R = %.6f ± %.6f\n", r->reflectance, r->reflectance_err);
    if (s->config == SOAK_MEASURE_SLAB)
        printf("transmittance T = %.6f ± %.6f\n", r->transmittance, r->transmittance_err);
    printf("%.6f ± %.6f\n", r->value, r->std_error);
}

int soak_cmd_measure(int argc, char **argv)
{
    measure_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc >= 0) return rc;
    if (!check_combination(&a)) return SOAK_EXIT_USAGE;
    soak_measure_setup *s = &a.setup;
    if (a.material && (rc = apply_material(&a)) >= 0) return rc;
    soak_status st = soak_measure_validate(s);
    if (st != SOAK_OK) {
        cli_error(CMD, "invalid parameter combination: %s", soak_status_str(st));
        return SOAK_EXIT_USAGE;
    }
    cli_progress p;
    cli_progress_start(&p, "measure", 1.0);
    s->progress = on_progress;
    s->progress_ctx = &p;
    double t0 = cli_now();
    soak_measure_result r;
    st = soak_measure_run(s, &r);
    cli_progress_finish(&p);
    if (st != SOAK_OK) {
        cli_error(CMD, "tracing %s failed: %s", config_name(s->config), soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    print_result(s, &r, cli_now() - t0);
    return SOAK_EXIT_OK;
}
