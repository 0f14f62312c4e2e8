/* soak measure: virtual gonio-reflectometer (soak/measure.h). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "soak/fresnel.h"
#include "soak/measure.h"
#include "soak/preset.h"
#include "soak/wetness.h"

static const char *CMD = "measure";

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak measure --config film|halfspace|slab [options]\n\n"
            "Traces photons through a canonical plane-parallel configuration and prints\n"
            "its reflectance (or a slab's transmittance). The last line of the output is\n"
            "'value ± standard error'.\n\n"
            "configuration:\n"
            "  --config NAME        film: smooth liquid film over a Lambertian base;\n"
            "                       halfspace: semi-infinite scattering medium;\n"
            "                       slab: scattering slab of optical thickness --tau\n"
            "  --incidence I        normal (default), diffuse, or an angle in degrees [0, 90)\n"
            "  --quantity R|T       reflectance (default) or transmittance (slab only)\n"
            "  --ior N              film / medium index relative to air, [1, 3]\n"
            "                       (default 1.333 for film, 1 = index-matched otherwise)\n"
            "film:\n"
            "  --base-albedo A      albedo of the Lambertian base, [0, 1] (required)\n"
            "  --film-alpha A       absorption coefficient of the liquid, 1/m (default 0)\n"
            "  --film-thickness D   film thickness, m (default 0: no absorption)\n"
            "halfspace, slab (lengths in mean free paths):\n"
            "  --albedo W           single-scattering albedo, [0, 1] (required)\n"
            "  --g G                single Henyey-Greenstein lobe (default 0: isotropic)\n"
            "  --g1 G --g2 G --w W  two-term HG (seed 000 Eq. 5), w weights the g1 lobe\n"
            "  --tau T              optical thickness of the slab, (0, 1e6] (slab, required)\n"
            "run:\n"
            "  --paths N            photons traced (default 1000000)\n"
            "  --seed S             RNG seed (default 1); results depend only on the seed\n"
            "  --threads N          worker threads (default: all online cores)\n"
            "  --max-events N       per-path cap on tracking steps (default 1000000);\n"
            "                       capped paths are counted and reported\n"
            "  --no-roulette        disable Russian roulette (slower; for checks)\n"
            "material presets (soak materials; replace the raw medium/film parameters):\n"
            "  --material NAME      preset name; needs --wetness\n"
            "  --wetness W          wetness in [0, 1], steady state (soak/wetness.h)\n"
            "  --channel r|g|b      colour channel to trace (default g)\n"
            "  --liquid NAME        liquid (default water)\n"
            "                       halfspace (default for a preset): the wet medium's omega and\n"
            "                       phase, index-matched unless --ior; slab: a thin sheet, tau =\n"
            "                       sigma_t * sheet thickness; film: the film over the wet\n"
            "                       subsurface albedo. The model's own value is printed alongside.\n\n"
            "examples:\n"
            "  soak measure --config film --base-albedo 0.5 --ior 1.33 --incidence normal --paths 200000\n"
            "  soak measure --config halfspace --albedo 0.9 --incidence 60\n"
            "  soak measure --config slab --tau 2 --albedo 0.9 --g 0.5 --quantity T\n"
            "  soak measure --material sand --wetness 1 --incidence diffuse --channel r\n");
}

typedef struct measure_args {
    soak_measure_setup setup;
    int have_config, have_ior, have_base, have_albedo, have_tau, have_g, have_g2;
    int have_g1, have_w;
    const char *material;
    const char *liquid;
    int have_wetness, have_channel, have_base_alpha;
    double wetness;
    int channel;
} measure_args;

static int parse_config(const char *v, soak_measure_config *c)
{
    if (strcmp(v, "film") == 0) *c = SOAK_MEASURE_FILM;
    else if (strcmp(v, "halfspace") == 0) *c = SOAK_MEASURE_HALFSPACE;
    else if (strcmp(v, "slab") == 0) *c = SOAK_MEASURE_SLAB;
    else {
        cli_error(CMD, "--config: unknown configuration '%s' (expected film, halfspace or slab)", v);
        return 0;
    }
    return 1;
}

static int parse_incidence(const char *v, soak_measure_setup *s)
{
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
    if (!cli_parse_double(CMD, "--incidence", v, 0.0, 90.0, &deg)) {
        cli_error(CMD, "--incidence: use normal, diffuse or an angle in degrees [0, 90)");
        return 0;
    }
    if (deg >= 90.0) {
        cli_error(CMD, "--incidence: %s degrees is grazing; use an angle below 90", v);
        return 0;
    }
    s->diffuse_incidence = 0;
    s->cos_incidence = cos(deg * SOAK_PI / 180.0);
    return 1;
}

/* Returns -1 to continue, or an exit code. */
static int parse_args(int argc, char **argv, measure_args *a)
{
    soak_measure_setup *s = &a->setup;
    for (int i = 1; i < argc; ++i) {
        const char *arg = argv[i];
        const char *v = NULL;
        long n;
        if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            usage(stdout);
            return SOAK_EXIT_OK;
        }
#define VALUE() \
    if (!(v = cli_value(CMD, argc, argv, &i))) return SOAK_EXIT_USAGE
        if (cli_is(arg, "--config")) {
            VALUE();
            if (!parse_config(v, &s->config)) return SOAK_EXIT_USAGE;
            a->have_config = 1;
        } else if (cli_is(arg, "--incidence")) {
            VALUE();
            if (!parse_incidence(v, s)) return SOAK_EXIT_USAGE;
        } else if (cli_is(arg, "--quantity")) {
            VALUE();
            if (strcmp(v, "R") == 0 || strcmp(v, "r") == 0) s->quantity = SOAK_MEASURE_R;
            else if (strcmp(v, "T") == 0 || strcmp(v, "t") == 0) s->quantity = SOAK_MEASURE_T;
            else {
                cli_error(CMD, "--quantity: expected R or T, got '%s'", v);
                return SOAK_EXIT_USAGE;
            }
        } else if (cli_is(arg, "--ior")) {
            VALUE();
            if (!cli_parse_double(CMD, "--ior", v, 1.0, 3.0, &s->ior)) return SOAK_EXIT_USAGE;
            a->have_ior = 1;
        } else if (cli_is(arg, "--base-albedo")) {
            VALUE();
            if (!cli_parse_double(CMD, "--base-albedo", v, 0.0, 1.0, &s->base_albedo)) return SOAK_EXIT_USAGE;
            a->have_base = 1;
        } else if (cli_is(arg, "--film-alpha")) {
            VALUE();
            if (!cli_parse_double(CMD, "--film-alpha", v, 0.0, 1e6, &s->film_alpha)) return SOAK_EXIT_USAGE;
            a->have_base_alpha = 1;
        } else if (cli_is(arg, "--film-thickness")) {
            VALUE();
            if (!cli_parse_double(CMD, "--film-thickness", v, 0.0, 1e3, &s->film_thickness)) return SOAK_EXIT_USAGE;
            a->have_base_alpha = 1;
        } else if (cli_is(arg, "--albedo")) {
            VALUE();
            if (!cli_parse_double(CMD, "--albedo", v, 0.0, 1.0, &s->albedo)) return SOAK_EXIT_USAGE;
            a->have_albedo = 1;
        } else if (cli_is(arg, "--g")) {
            VALUE();
            if (!cli_parse_double(CMD, "--g", v, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, &s->phase.g1)) return SOAK_EXIT_USAGE;
            s->phase.g2 = s->phase.g1;
            s->phase.w = 1.0;
            a->have_g = 1;
        } else if (cli_is(arg, "--g1")) {
            VALUE();
            if (!cli_parse_double(CMD, "--g1", v, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, &s->phase.g1)) return SOAK_EXIT_USAGE;
            a->have_g1 = 1;
        } else if (cli_is(arg, "--g2")) {
            VALUE();
            if (!cli_parse_double(CMD, "--g2", v, -SOAK_HG_G_MAX, SOAK_HG_G_MAX, &s->phase.g2)) return SOAK_EXIT_USAGE;
            a->have_g2 = 1;
        } else if (cli_is(arg, "--w")) {
            VALUE();
            if (!cli_parse_double(CMD, "--w", v, 0.0, 1.0, &s->phase.w)) return SOAK_EXIT_USAGE;
            a->have_w = 1;
        } else if (cli_is(arg, "--tau")) {
            VALUE();
            if (!cli_parse_double(CMD, "--tau", v, 0.0, 1e6, &s->tau)) return SOAK_EXIT_USAGE;
            if (!(s->tau > 0.0)) {
                cli_error(CMD, "--tau: the optical thickness must be > 0, got '%s'", v);
                return SOAK_EXIT_USAGE;
            }
            a->have_tau = 1;
        } else if (cli_is(arg, "--paths")) {
            VALUE();
            if (!cli_parse_int(CMD, "--paths", v, 1, 1000000000000L, &n)) return SOAK_EXIT_USAGE;
            s->paths = n;
        } else if (cli_is(arg, "--seed")) {
            VALUE();
            if (!cli_parse_int(CMD, "--seed", v, 0, 0x7fffffffffffffffL, &n)) return SOAK_EXIT_USAGE;
            s->seed = (uint64_t)n;
        } else if (cli_is(arg, "--threads")) {
            VALUE();
            if (!cli_parse_int(CMD, "--threads", v, 1, 256, &n)) return SOAK_EXIT_USAGE;
            s->threads = (int)n;
        } else if (cli_is(arg, "--max-events")) {
            VALUE();
            if (!cli_parse_int(CMD, "--max-events", v, 1, 1000000000000L, &n)) return SOAK_EXIT_USAGE;
            s->max_events = n;
        } else if (strcmp(arg, "--no-roulette") == 0) {
            s->roulette = 0;
        } else if (cli_is(arg, "--material")) {
            VALUE();
            a->material = v;
        } else if (cli_is(arg, "--wetness")) {
            VALUE();
            if (!cli_parse_double(CMD, "--wetness", v, 0.0, 1.0, &a->wetness)) return SOAK_EXIT_USAGE;
            a->have_wetness = 1;
        } else if (cli_is(arg, "--liquid")) {
            VALUE();
            a->liquid = v;
        } else if (cli_is(arg, "--channel")) {
            VALUE();
            if (strcmp(v, "r") == 0) a->channel = 0;
            else if (strcmp(v, "g") == 0) a->channel = 1;
            else if (strcmp(v, "b") == 0) a->channel = 2;
            else {
                cli_error(CMD, "--channel: expected r, g or b, got '%s'", v);
                return SOAK_EXIT_USAGE;
            }
            a->have_channel = 1;
        } else {
            cli_error(CMD, "unknown option '%s' (see 'soak measure --help')", arg);
            return SOAK_EXIT_USAGE;
        }
#undef VALUE
    }
    return -1;
}

static int check_combination(measure_args *a)
{
    soak_measure_setup *s = &a->setup;
    if (a->material || a->have_wetness || a->have_channel || a->liquid) {
        if (!a->material || !a->have_wetness) {
            cli_error(CMD, "%s: a preset needs both --material NAME and --wetness W",
                      a->material ? "--wetness" : "--material");
            return 0;
        }
        if (a->have_albedo || a->have_tau || a->have_g || a->have_g1 || a->have_g2 || a->have_w || a->have_base ||
            a->have_base_alpha) {
            cli_error(CMD, "--material: replaces --albedo/--g*/--tau/--base-albedo/--film-*; give one or the other");
            return 0;
        }
        if (!a->have_config) s->config = SOAK_MEASURE_HALFSPACE;
        if (s->quantity == SOAK_MEASURE_T && s->config != SOAK_MEASURE_SLAB) {
            cli_error(CMD, "--quantity T: only a slab transmits");
            return 0;
        }
        return 1; /* the rest is checked once the preset is loaded */
    }
    if (!a->have_config) {
        cli_error(CMD, "--config is required (film, halfspace or slab)");
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
    if (s->config == SOAK_MEASURE_FILM) {
        if (!a->have_base) {
            cli_error(CMD, "--base-albedo is required for --config film");
            return 0;
        }
        if (!a->have_ior) s->ior = SOAK_WATER_IOR;
        if (a->have_albedo || a->have_tau || a->have_g || a->have_g1) {
            cli_error(CMD, "--albedo/--tau/--g*: not used by --config film (it has no scattering medium)");
            return 0;
        }
    } else {
        if (!a->have_albedo) {
            cli_error(CMD, "--albedo is required for --config %s",
                      s->config == SOAK_MEASURE_SLAB ? "slab" : "halfspace");
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
    }
    if (s->quantity == SOAK_MEASURE_T && s->config != SOAK_MEASURE_SLAB) {
        cli_error(CMD, "--quantity T: only a slab transmits");
        return 0;
    }
    return 1;
}

/* Fills the setup from a preset at the given wetness (steady state) for one
 * colour channel; prints the model's own value for comparison. Returns an
 * exit code, or -1 to go on. */
static int apply_material(measure_args *a)
{
    soak_measure_setup *s = &a->setup;
    char err[512] = "";
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(NULL, &db, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "--material: cannot load the presets: %s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    int rc = -1;
    const soak_preset *p = soak_presets_find(db, a->material);
    const char *liquid_name = a->liquid ? a->liquid : "water";
    const soak_liquid *liq = soak_presets_find_liquid(db, liquid_name);
    soak_wet_params wp;
    if (!p) {
        cli_error(CMD, "--material: no preset named '%s' in %s (see 'soak materials')", a->material,
                  soak_presets_path(db));
        rc = SOAK_EXIT_USAGE;
    } else if (!liq) {
        cli_error(CMD, "--liquid: no liquid named '%s' in %s", liquid_name, soak_presets_path(db));
        rc = SOAK_EXIT_USAGE;
    } else if (p->kind == SOAK_KIND_CONDUCTOR) {
        cli_error(CMD, "--material: '%s' is a conductor: it has neither a scattering medium nor a Lambertian base",
                  a->material);
        rc = SOAK_EXIT_USAGE;
    } else {
        soak_wet_input in = soak_wet_input_steady(p, a->wetness);
        st = soak_wetness_eval(p, liq, &in, &wp);
        if (st != SOAK_OK) {
            cli_error(CMD, "--material %s --wetness %g: wetness model failed: %s", a->material, a->wetness,
                      soak_status_str(st));
            rc = SOAK_EXIT_FAIL;
        }
    }
    if (rc >= 0) {
        soak_presets_free(db);
        return rc;
    }
    int c = a->have_channel ? a->channel : 1;
    const char *cname = c == 0 ? "r" : (c == 1 ? "g" : "b");
    printf("material: %s, wetness %g, liquid %s, channel %s (pore fill %.3f, film coverage %.3f)\n", p->name,
           a->wetness, liquid_name, cname, wp.fill, wp.film_coverage);
    if (s->config == SOAK_MEASURE_FILM) {
        s->base_albedo = soak_rgb_at(wp.albedo_subsurface, c);
        s->ior = wp.film_ior;
        s->film_alpha = soak_rgb_at(wp.film_absorption_per_m, c);
        s->film_thickness = wp.film_thickness_m;
        if (!(s->film_alpha <= 1e6 && s->film_thickness <= 1e3)) {
            cli_error(CMD, "--material: film parameters of '%s' out of the tracer's range", a->material);
            rc = SOAK_EXIT_USAGE;
        }
        printf("model: subsurface albedo %.6f; film albedo at full coverage %.6f (diffuse part, diffuse light)\n",
               s->base_albedo, soak_rgb_at(wp.albedo_film, c));
    } else {
        s->albedo = soak_rgb_at(wp.omega, c);
        s->phase = wp.phase;
        if (!a->have_ior) s->ior = 1.0;
        if (s->config == SOAK_MEASURE_SLAB) {
            s->tau = soak_rgb_at(p->sigma_t, c) * p->thickness_mm;
            if (!(s->tau > 0.0 && s->tau <= 1e6)) {
                cli_error(CMD, "--config slab: preset '%s' is not a thin sheet (no finite thickness)", a->material);
                rc = SOAK_EXIT_USAGE;
            }
        }
        printf("model: subsurface albedo %.6f (van de Hulst, semi-infinite, index-matched, diffuse light)\n",
               soak_rgb_at(wp.albedo_subsurface, c));
    }
    soak_presets_free(db);
    return rc;
}

static void on_progress(void *ctx, double fraction)
{
    cli_progress_update(ctx, fraction);
}

static const char *config_name(soak_measure_config c)
{
    return c == SOAK_MEASURE_FILM ? "film" : (c == SOAK_MEASURE_SLAB ? "slab" : "halfspace");
}

static void print_setup(const soak_measure_setup *s)
{
    printf("config: %s, ior %g", config_name(s->config), s->ior);
    if (s->config == SOAK_MEASURE_FILM) {
        printf(", base albedo %g", s->base_albedo);
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

int soak_cmd_measure(int argc, char **argv)
{
    measure_args a;
    memset(&a, 0, sizeof a);
    soak_measure_setup_default(&a.setup);
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    a.setup.threads = cores >= 1 && cores <= 256 ? (int)cores : 1;
    a.setup.phase.w = 1.0;
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
    print_setup(s);
    printf("mean tracking steps per path: %.3f (%.2f s)\n", r.mean_events, cli_now() - t0);
    printf("capped paths: %lld (unscored throughput per path %.3g)\n", r.capped, r.capped_weight);
    printf("reflectance R = %.6f ± %.6f\n", r.reflectance, r.reflectance_err);
    if (s->config == SOAK_MEASURE_SLAB)
        printf("transmittance T = %.6f ± %.6f\n", r.transmittance, r.transmittance_err);
    printf("%.6f ± %.6f\n", r.value, r.std_error);
    return SOAK_EXIT_OK;
}
