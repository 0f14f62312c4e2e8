/* soak albedo: dry and wet albedo of a preset (soak/wetness.h), or the
 * closed-form albedo of a liquid film over a Lambertian base (soak/film.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "soak/film.h"
#include "soak/export.h"
#include "soak/preset.h"
#include "soak/sheet.h"
#include "soak/wetness.h"

static const char *CMD = "albedo";

static int usage_error(const char *message)
{
    cli_error(CMD, "%s", message);
    return SOAK_EXIT_USAGE;
}

static void list_materials(const soak_preset_db *db)
{
    fprintf(stderr, "known materials:");
    for (int i = 0; i < soak_presets_count(db); ++i) fprintf(stderr, " %s", soak_presets_at(db, i)->name);
    fprintf(stderr, "\n");
}

static void list_liquids(const soak_preset_db *db)
{
    fprintf(stderr, "known liquids:");
    for (int i = 0; i < soak_presets_liquid_count(db); ++i) fprintf(stderr, " %s", soak_presets_liquid_at(db, i)->name);
    fprintf(stderr, "\n");
}

typedef struct opts {
    const char *model, *material, *liquid, *file, *incidence, *base_colour;
    int has_wetness, has_time, has_t0, has_fill, has_film, has_base, has_ior, has_thick, has_abs, has_sun;
    double wetness, time, t0, fill, film, base, ior, thickness, absorption, sun_zenith;
} opts;

#define F(field) CLI_FIELD(opts, field)
#define SEEN(field) CLI_SEEN(opts, field)
static const cli_opt albedo_opts[] = {
    {"", NULL, CLI_OPT_HEADING, .help = "preset mode options:"},
    {"--material", NULL, CLI_OPT_STRING, F(material), .meta = "NAME", .help = "preset (soak materials)"},
    {"--wetness", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(wetness), SEEN(has_wetness), .meta = "W",
     .help = "wetness, %R"},
    {"--time", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_WET_TIME_MAX, .hi = SOAK_WET_TIME_MAX, F(time), SEEN(has_time),
     .meta = "T", .help = "time (default 1)"},
    {"--t0", NULL, CLI_OPT_DOUBLE, .lo = -SOAK_WET_TIME_MAX, .hi = SOAK_WET_TIME_MAX, F(t0), SEEN(has_t0),
     .meta = "T0", .help = "wet-map start time (default 0)"},
    {"--fill-time", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_WET_TIME_MAX, F(fill), SEEN(has_fill), .meta = "TF",
     .help = "pore fill time (default: the preset's; 0 fills instantly)"},
    {"--film-thickness", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_WET_FILM_MAX_M, F(film), SEEN(has_film),
     .meta = "M", .help = "film thickness, %R m (default: the preset's)"},
    {"--liquid", NULL, CLI_OPT_STRING, F(liquid), .meta = "NAME", .help = "liquid (default water)"},
    {"--base-colour", NULL, CLI_OPT_STRING, F(base_colour), .meta = "R,G,B",
     .help = "your own dry colour (linear RGB, or V for grey)"},
    {"--sun-zenith", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 90, F(sun_zenith), SEEN(has_sun), .meta = "DEG",
     .help = "also the albedo under a sun DEG degrees from the normal, %R"},
    {"--materials", NULL, CLI_OPT_STRING, F(file), .meta = "FILE",
     .help = "preset file (default: $SOAK_MATERIALS, else the shipped one)"},
    {"", NULL, CLI_OPT_HEADING, .help = "film mode options:"},
    {"--model", NULL, CLI_OPT_STRING, F(model), .meta = "film", .help = "the closed-form film albedo"},
    {"--base-albedo", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = 1, F(base), SEEN(has_base), .meta = "A",
     .help = "albedo of the Lambertian base, %R"},
    {"--ior", NULL, CLI_OPT_DOUBLE, .lo = SOAK_FILM_MIN_N, .hi = SOAK_FILM_MAX_N, F(ior), SEEN(has_ior), .meta = "N",
     .help = "film index, %R"},
    {"--incidence", NULL, CLI_OPT_STRING, F(incidence), .meta = "I", .help = "normal, diffuse or DEG (0..90)"},
    {"--thickness", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_FILM_MAX_THICKNESS, F(thickness), SEEN(has_thick),
     .meta = "M", .help = "film thickness, %R m (default 0)"},
    {"--absorption", NULL, CLI_OPT_DOUBLE, .lo = 0, .hi = SOAK_FILM_MAX_ALPHA, F(absorption), SEEN(has_abs),
     .meta = "ALPHA", .help = "absorption of the liquid, %R 1/m (default 0: none)"},
};
#undef F
#undef SEEN

static void usage(FILE *out)
{
    fprintf(out,
            "usage: soak albedo --material NAME --wetness W [--time T] [--t0 T0]\n"
            "                   [--fill-time TF] [--film-thickness M] [--liquid NAME]\n"
            "                   [--base-colour R,G,B] [--sun-zenith DEG] [--materials FILE]\n"
            "       soak albedo --model film --base-albedo A --ior N\n"
            "                   --incidence normal|diffuse|DEG [--thickness M] [--absorption ALPHA]\n\n"
            "Preset mode prints the dry albedo and the wet albedo (linear RGB) of a\n"
            "material preset: W in [0,1] is the wetness; T, T0 and TF are the time, the\n"
            "wet-map start time and the pore fill time (Hnat et al. 2006; defaults 1, 0\n"
            "and the preset's; TF = 0 fills instantly); M is the film thickness in metres\n"
            "(default: the preset's). The chain is documented in soak/wetness.h.\n"
            "--base-colour wets your own dry colour (a texture's linear RGB, or V for\n"
            "grey) with the preset's class instead of its own colour (soak/export.h).\n"
            "Also printed: the liquid-air interface's share of the surface (it weights\n"
            "the liquid's Fresnel mirror), the GGX alpha, a thin sheet's transmittance.\n"
            "The wet albedos are for uniform diffuse light (bihemispherical: an overcast\n"
            "sky); --sun-zenith adds the directional-hemispherical albedo for a sun DEG\n"
            "degrees (0..90) from the normal, as field albedos are measured (the dry\n"
            "body is Lambertian, so its albedo is the same under both lights).\n\n"
            "Film mode prints the total reflectance of a smooth liquid film of index N\n"
            "(1..3) over a Lambertian base of albedo A (Lekner & Dorf 1988), for light at\n"
            "normal incidence, uniform diffuse light, or DEG degrees (0..90) from the\n"
            "normal; --thickness in metres and --absorption in 1/m (default 0: no\n"
            "absorption). The result is the single number on the last line.\n\n");
    const cli_opt_table tables[] = {CLI_TABLE(albedo_opts, NULL)};
    cli_opts_help(out, tables, 1);
    fprintf(out,
            "\nexamples:\n"
            "  soak albedo --material sand --wetness 1\n"
            "  soak albedo --material paper --wetness 0.3 --time 0.2 --t0 0.1 --fill-time 0.3\n"
            "  soak albedo --material brick --wetness 0.6 --base-colour 0.45,0.2,0.12\n"
            "  soak albedo --material asphalt --wetness 1 --sun-zenith 30\n"
            "  soak albedo --model film --base-albedo 0.5 --ior 1.33 --incidence diffuse\n");
}

/* Returns -1 to continue, else an exit code. */
static int parse(int argc, char **argv, opts *o)
{
    memset(o, 0, sizeof *o);
    const cli_spec spec = {CMD, "argument", "'soak albedo --help'", usage, NULL, NULL};
    const cli_opt_table tables[] = {CLI_TABLE(albedo_opts, o)};
    return cli_opts_parse(&spec, tables, 1, argc, argv);
}

static int run_film(const opts *o)
{
    if (o->material || o->liquid || o->file || o->has_wetness || o->has_time || o->has_t0 || o->has_fill ||
        o->has_film || o->base_colour || o->has_sun)
        return usage_error("--model film takes --base-albedo, --ior, --incidence, --thickness and --absorption only");
    if (!o->has_base) return usage_error("--base-albedo is required with --model film");
    if (!o->has_ior) return usage_error("--ior is required with --model film");
    if (!o->incidence) return usage_error("--incidence is required with --model film");
    int diffuse = 0;
    double deg = 0.0;
    if (strcmp(o->incidence, "diffuse") == 0)
        diffuse = 1;
    else if (strcmp(o->incidence, "normal") != 0 &&
             !cli_parse_double(CMD, "--incidence (normal, diffuse or degrees)", o->incidence, 0.0, 90.0, &deg))
        return SOAK_EXIT_USAGE;

    soak_film film = {o->ior, o->has_abs ? o->absorption : 0.0, o->has_thick ? o->thickness : 0.0};
    double albedo = 0.0;
    /* cos(90 deg) in floating point is 6e-17, not 0: snap so 90 means grazing. */
    double cos_i = deg >= 90.0 ? 0.0 : cos(deg * (SOAK_PI / 180.0));
    soak_status st = diffuse ? soak_film_albedo_diffuse(&film, o->base, &albedo)
                             : soak_film_albedo_dir(&film, o->base, cos_i, &albedo);
    if (st != SOAK_OK) {
        cli_error(CMD, "film albedo (base %g, ior %g, incidence %s) failed: %s", o->base, o->ior, o->incidence,
                  soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    printf("film model (Lekner & Dorf 1988): base albedo %g, ior %g, incidence %s, thickness %g m, absorption %g 1/m\n",
           o->base, o->ior, o->incidence, film.thickness, film.alpha);
    printf("total reflectance (film specular + diffuse through the film):\n");
    printf("%.10g\n", albedo);
    return SOAK_EXIT_OK;
}

/* The wetness input of the options over the preset's defaults. */
static soak_wet_input wet_input(const opts *o, const soak_preset *p)
{
    soak_wet_input in = soak_wet_input_steady(p, o->wetness);
    in.t_fill = p->t_fill;
    if (o->has_time) in.time = o->time;
    if (o->has_t0) in.t0 = o->t0;
    if (o->has_fill) in.t_fill = o->fill;
    if (o->has_film) in.film_thickness_m = o->film;
    return in;
}

typedef struct wet_albedos {
    soak_wet_input in;
    soak_rgb base;          /* the dry albedo: the preset's or --base-colour */
    soak_wet_params w;
    soak_rgb sun, sun_total; /* --sun-zenith */
    soak_rgb sheet;          /* thin sheets' transmittance */
} wet_albedos;

/* Returns -1 with r filled, else the exit code (the error printed). */
static int compute(const opts *o, const soak_preset *p, const soak_liquid *l, wet_albedos *r)
{
    memset(r, 0, sizeof *r);
    r->in = wet_input(o, p);
    r->base = p->albedo;
    if (o->base_colour && !cli_parse_rgb(CMD, "--base-colour", o->base_colour, 0.0, 1.0, &r->base))
        return SOAK_EXIT_USAGE;
    soak_status st = o->base_colour ? soak_wet_params_for_base(p, l, &r->in, r->base, &r->w)
                                    : soak_wetness_eval(p, l, &r->in, &r->w);
    /* cos(90 deg) in floating point is 6e-17, not 0: snap so 90 means grazing. */
    double cos_sun = o->sun_zenith >= 90.0 ? 0.0 : cos(o->sun_zenith * (SOAK_PI / 180.0));
    if (st == SOAK_OK && o->has_sun) st = soak_wetness_albedo_sun(p, l, &r->w, cos_sun, &r->sun, &r->sun_total);
    if (st == SOAK_OK && p->kind == SOAK_KIND_THIN_SHEET)
        st = soak_sheet_transmittance(&r->w, p->thickness_m, p->ior, &r->sheet);
    if (st != SOAK_OK) {
        cli_error(CMD, "material %s, wetness %g: wetness mapping failed: %s", p->name, o->wetness, soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    return -1;
}

static void print_albedos(const opts *o, const soak_preset *p, const soak_liquid *l, const wet_albedos *r)
{
    const soak_wet_params *w = &r->w;
    printf("material %s (%s), kind %s, liquid %s\n", p->name, p->display_name, soak_material_kind_name(p->kind),
           l->name);
    printf("wetness %g, time %g, t0 %g, fill time %g, film thickness %g m\n", r->in.wetness, r->in.time, r->in.t0,
           r->in.t_fill, r->in.film_thickness_m);
    printf("pore fill %.4f, film coverage %.4f\n", w->fill, w->film_coverage);
    printf("dry albedo        %.6f %.6f %.6f%s\n", r->base.r, r->base.g, r->base.b,
           o->base_colour ? " (--base-colour)" : "");
    printf("wet albedo        %.6f %.6f %.6f\n", w->albedo.r, w->albedo.g, w->albedo.b);
    printf("wet albedo total  %.6f %.6f %.6f\n", w->albedo_total.r, w->albedo_total.g, w->albedo_total.b);
    if (o->has_sun) {
        printf("under a sun at zenith %g deg (directional-hemispherical; above: uniform diffuse light):\n",
               o->sun_zenith);
        printf("sun wet albedo    %.6f %.6f %.6f\n", r->sun.r, r->sun.g, r->sun.b);
        printf("sun albedo total  %.6f %.6f %.6f\n", r->sun_total.r, r->sun_total.g, r->sun_total.b);
    }
    printf("interface area    %.6f\n", soak_wet_interface_area(w));
    printf("ggx alpha         %.6f\n", w->ggx_alpha);
    if (p->kind == SOAK_KIND_THIN_SHEET)
        printf("sheet transmit.   %.6f %.6f %.6f\n", r->sheet.r, r->sheet.g, r->sheet.b);
}

static int run_preset(const opts *o)
{
    if (o->has_base || o->has_ior || o->incidence || o->has_thick || o->has_abs)
        return usage_error("--base-albedo, --ior, --incidence, --thickness and --absorption need --model film");
    if (!o->material) return usage_error("--material is required (or --model film)");
    if (!o->has_wetness) return usage_error("--wetness is required");
    char err[1024];
    soak_preset_db *db = NULL;
    soak_status st = soak_presets_load(o->file, &db, err, sizeof err);
    if (st != SOAK_OK) {
        cli_error(CMD, "%s", err[0] ? err : soak_status_str(st));
        return SOAK_EXIT_FAIL;
    }
    int rc = SOAK_EXIT_USAGE;
    const soak_preset *p = soak_presets_find(db, o->material);
    const soak_liquid *l = soak_presets_find_liquid(db, o->liquid ? o->liquid : "water");
    wet_albedos r;
    if (!p) {
        cli_error(CMD, "--material: unknown material '%s'", o->material);
        list_materials(db);
    } else if (!l) {
        cli_error(CMD, "--liquid: unknown liquid '%s'", o->liquid);
        list_liquids(db);
    } else if ((rc = compute(o, p, l, &r)) < 0) {
        print_albedos(o, p, l, &r);
        rc = SOAK_EXIT_OK;
    }
    soak_presets_free(db);
    return rc;
}

int soak_cmd_albedo(int argc, char **argv)
{
    opts o;
    int rc = parse(argc, argv, &o);
    if (rc >= 0) return rc;
    if (o.model && strcmp(o.model, "film") != 0) {
        cli_error(CMD, "--model: unknown model '%s' (known: film)", o.model);
        return SOAK_EXIT_USAGE;
    }
    return o.model ? run_film(&o) : run_preset(&o);
}
