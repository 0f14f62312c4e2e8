/* soak export --target povray: povray/soak_materials.inc, the data the
 * macros of povray/soak.inc interpolate and assemble.
 *
 * Everything POV-Ray needs is computed here, for POV-Ray 3.7's own shading
 * model (checked by rendering, see povray/README.md "POV-Ray's conventions"):
 *   - pigment: the diffuse albedo under the film (soak_wet_params.albedo),
 *     the film's darkening included, since POV-Ray's finish does not darken
 *     the base under a reflection block;
 *   - film: reflection { 0, R fresnel on } gives R times the Fresnel
 *     reflectance of interior { ior n_liquid }; R = coverage (the film) plus
 *     the uncovered share of the liquid-filled pores (water_specular_weight);
 *   - the material's own rough surface: specular albedo S roughness r, with
 *     S = specular_weight * (1 - c) * F0(n) (POV-Ray's "albedo" normalises
 *     the Blinn lobe to hemispherical albedo S at normal view) and
 *     r = 1 / n_Blinn, n_Blinn = 2 / alpha^2 - 2 (Walter et al. 2007, GGX
 *     vs. Blinn-Phong width), clamped to POV-Ray's [5e-4, 1];
 *   - the liquid's sun glint: phong albedo R * F0(n_liquid);
 *   - conductors: reflection { rgb albedo_total } (the metal seen through the
 *     film, plus the film's own specular, normal incidence);
 *   - thin sheets: two-flux transmittance with the faces (soak/sheet.h) and the
 *     backside diffuse amount of POV-Ray's "diffuse front, back", luminance
 *     matched: back = Y(T) / Y(pigment) (POV-Ray tints it by the pigment);
 *   - the scattering medium for participating media and subsurface: sigma_s,
 *     sigma_a (per channel, in 1/mm: POV-Ray's files are in mm, converted
 *     from the core's 1/m here, soak/units.h), the two-term Henyey-Greenstein phase
 *     (g1, g2, weight w of g1; all 0 where there is no medium: conductors);
 *     and POV-Ray's subsurface translucency giving its BSSRDF, which takes
 *     the reduced albedo from the pigment, the core's diffusion length
 *     sqrt(3 sigma_a (sigma_a + (1 - g) sigma_s)), g = w g1 + (1 - w) g2
 *     (soak/povray_subsurface.h);
 *   - the wetness function for any base colour (soak_wet_params_for_base)
 *     on the nodes of soak_export_base_nodes, as <r,g,b> per (wetness, dry
 *     albedo) node;
 *   - the view factor (soak_wetness_view_factor) per knot on a grid of view
 *     angles, every 5 deg to 60 deg, then every 2.5 deg to 90 deg: POV-Ray's
 *     aoi pattern is linear in the angle (1 - angle / 180 deg), so soak.inc's
 *     colour_map over it lerps in angle; this grid keeps albedo x factor so
 *     lerped within 0.0008 of the core to 60 deg and 0.0011 to 75 deg over
 *     every preset's knots (0.0064 to 90 deg; paper, fully wet);
 *   - the pore-filling schedule as a macro (Soak_Fill_Progress_Fn), the one
 *     copy soak.inc's animation macros call.
 * Layout: flat arrays indexed by table t = preset * Soak_N_Liquids + liquid
 * (POV-Ray 3.7 has no dictionaries), with start/count arrays. Numbers are
 * printed with 7 significant digits: the same preset file gives the same
 * bytes on every machine. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/export.h"
#include "soak/export_escape.h"
#include "soak/fresnel.h"
#include "soak/povray_subsurface.h"
#include "soak/sheet.h"
#include "soak/units.h"

#define POV_ROUGH_MIN 5e-4
#define POV_ROUGH_MAX 1.0
#define POV_FORMAT_VERSION 5
#define POV_SUBSURFACE_PIGMENT_MIN 1e-3 /* soak.inc's clamp of a subsurface pigment */
#define POV_VIEW_N 25

enum { V_PIGMENT, V_REFLECT_METAL, V_SHEET_T, V_SIGMA_S, V_SIGMA_A, V_TRANSLUCENCY, V_COUNT };
enum { S_W, S_COVERAGE, S_FILL, S_FILM_R, S_SPEC, S_ROUGH, S_PHONG, S_BACK, S_G1, S_G2, S_LOBE_W, S_COUNT };

static const char *const vec_names[V_COUNT] = {"Soak_K_Pigment", "Soak_K_Metal_Reflect", "Soak_K_Sheet_T",
                                               "Soak_K_Sigma_S", "Soak_K_Sigma_A",       "Soak_K_Translucency"};
static const char *const scal_names[S_COUNT] = {"Soak_K_W",    "Soak_K_Coverage", "Soak_K_Fill",  "Soak_K_Film_Reflect",
                                                "Soak_K_Spec", "Soak_K_Rough",    "Soak_K_Phong", "Soak_K_Sheet_Back",
                                                "Soak_K_G1",   "Soak_K_G2",       "Soak_K_Lobe_W"};
static const char *const vec_docs[V_COUNT] = {
    "diffuse albedo under the film, film darkening included (pigment, finish diffuse 1)",
    "conductors: mirror reflectance of the metal under the film incl. the film's specular (reflection rgb)",
    "thin sheets: two-flux diffuse transmittance, faces included",
    "scattering coefficient sigma_s, 1/mm (0: no medium)",
    "absorption coefficient sigma_a, 1/mm",
    "POV-Ray subsurface translucency, mm: the core's diffusion length under this pigment (0: no medium)"};
static const char *const scal_docs[S_COUNT] = {
    "wetness knot",
    "film coverage c",
    "pore fill f",
    "R of reflection { 0, R fresnel on } with interior { ior n_liquid }",
    "specular albedo of the material's own rough surface",
    "POV-Ray roughness of that highlight (1 / Blinn exponent)",
    "phong albedo of the liquid's sun glint",
    "thin sheets: backside amount of diffuse 1, B (0 otherwise)",
    "Henyey-Greenstein asymmetry g1 (forward lobe)",
    "Henyey-Greenstein asymmetry g2",
    "weight w of the g1 lobe"};

typedef struct pov_table {
    int n; /* knots */
    double s[S_COUNT][SOAK_EXPORT_KNOTS_MAX];
    soak_rgb v[V_COUNT][SOAK_EXPORT_KNOTS_MAX];
    int na, nw; /* base-colour nodes */
    double a[SOAK_EXPORT_KNOTS_MAX], w[SOAK_EXPORT_KNOTS_MAX];
    soak_rgb *base; /* nw * na, row-major in wetness */
    soak_rgb *view; /* n * POV_VIEW_N: the view factor per knot and view angle */
} pov_table;

typedef struct pov_out {
    FILE *f;
    int bad;
} pov_out;

static void out(pov_out *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (vfprintf(o->f, fmt, ap) < 0) o->bad = 1;
    va_end(ap);
}

static double clamp(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* GGX alpha -> POV-Ray roughness (1 / Blinn exponent). */
static double pov_roughness(double alpha)
{
    double a2 = alpha * alpha;
    double n = a2 >= 1.0 ? 0.0 : 2.0 / a2 - 2.0;
    return n <= 1.0 ? POV_ROUGH_MAX : clamp(1.0 / n, POV_ROUGH_MIN, POV_ROUGH_MAX);
}

/* The medium; metals have none (all zero). The translucency is computed for
 * the pigment soak.inc hands POV-Ray (clamped as there) and the liquid's ior
 * (the interior's). */
static soak_status fill_medium(const soak_wet_params *w, double eta, pov_table *t, int i)
{
    const double g = w->phase.w * w->phase.g1 + (1.0 - w->phase.w) * w->phase.g2;
    t->v[V_SIGMA_S][i] = soak_rgb_per_mm_from_per_m(w->sigma_s_per_m);
    t->v[V_SIGMA_A][i] = soak_rgb_per_mm_from_per_m(w->sigma_a_per_m);
    for (int k = 0; k < 3; ++k) {
        double sa = soak_rgb_at(w->sigma_a_per_m, k);
        double reduced = sa + (1.0 - g) * soak_rgb_at(w->sigma_s_per_m, k);
        double translucency = 0.0;
        if (reduced > 0.0) {
            double rd = clamp(soak_rgb_at(t->v[V_PIGMENT][i], k), POV_SUBSURFACE_PIGMENT_MIN, 1.0);
            soak_status st = soak_povray_translucency(rd, eta, sqrt(3.0 * sa * reduced), &translucency);
            if (st != SOAK_OK) return st;
        }
        soak_rgb_set(&t->v[V_TRANSLUCENCY][i], k, translucency);
    }
    t->s[S_G1][i] = w->phase.g1;
    t->s[S_G2][i] = w->phase.g2;
    t->s[S_LOBE_W][i] = w->phase.w;
    return SOAK_OK;
}

static double view_angle_deg(int k) { return k <= 12 ? 5.0 * k : 60.0 + 2.5 * (k - 12); }

static double view_cos(int k)
{
    const double deg = 0.017453292519943295;
    return k + 1 == POV_VIEW_N ? 0.0 : cos(view_angle_deg(k) * deg);
}

static soak_status fill_view(const soak_preset *p, const soak_liquid *l, const soak_wet_params *w, pov_table *t, int i)
{
    soak_status st = SOAK_OK;
    for (int k = 0; st == SOAK_OK && k < POV_VIEW_N; ++k)
        st = soak_wetness_view_factor(p, l, w, view_cos(k), &t->view[i * POV_VIEW_N + k]);
    return st;
}

static soak_status fill_knot(const soak_preset *p, const soak_liquid *l, double wet, pov_table *t, int i)
{
    soak_wet_input in = soak_wet_input_steady(p, wet);
    soak_wet_params w;
    soak_status st = soak_wetness_eval(p, l, &in, &w);
    double f0_liq = 0.0, f0_mat = 0.0;
    if (st == SOAK_OK) st = soak_fresnel_r0(l->ior, 0.0, &f0_liq);
    if (st == SOAK_OK && p->kind != SOAK_KIND_CONDUCTOR) st = soak_fresnel_r0(p->ior, 0.0, &f0_mat);
    soak_rgb sheet_t = {0, 0, 0};
    if (st == SOAK_OK && p->kind == SOAK_KIND_THIN_SHEET) st = soak_sheet_transmittance(&w, p->thickness_m, p->ior, &sheet_t);
    if (st == SOAK_OK) st = fill_view(p, l, &w, t, i);
    if (st != SOAK_OK) return st;
    const double c = w.film ? w.film_coverage : 0.0;
    const int metal = p->kind == SOAK_KIND_CONDUCTOR;
    const double film_r = soak_wet_interface_area(&w);
    t->s[S_W][i] = wet;
    t->s[S_COVERAGE][i] = c;
    t->s[S_FILL][i] = w.fill;
    t->s[S_FILM_R][i] = metal ? 0.0 : film_r;
    t->s[S_SPEC][i] = metal ? 0.0 : w.specular_weight * (1.0 - c) * f0_mat;
    t->s[S_ROUGH][i] = pov_roughness(w.ggx_alpha);
    t->s[S_PHONG][i] = film_r * f0_liq;
    for (int k = 0; k < 3; ++k) soak_rgb_set(&t->v[V_PIGMENT][i], k, clamp(soak_rgb_at(w.albedo, k), 0.0, 1.0));
    t->v[V_REFLECT_METAL][i] = metal ? w.albedo_total : (soak_rgb){0, 0, 0};
    t->v[V_SHEET_T][i] = sheet_t;
    double yp = soak_rgb_luminance(t->v[V_PIGMENT][i]);
    t->s[S_BACK][i] = p->kind == SOAK_KIND_THIN_SHEET && yp > 1e-6 ? soak_rgb_luminance(sheet_t) / yp : 0.0;
    return fill_medium(&w, l->ior, t, i);
}

static soak_status fill_table(const soak_preset *p, const soak_liquid *l, pov_table *t)
{
    double knots[SOAK_EXPORT_KNOTS_MAX];
    soak_status st = soak_export_knots(p, l, -1.0, knots, SOAK_EXPORT_KNOTS_MAX, &t->n);
    if (st == SOAK_OK) {
        t->view = malloc((size_t)t->n * POV_VIEW_N * sizeof *t->view);
        if (!t->view) return SOAK_ERR_NOMEM;
    }
    for (int i = 0; st == SOAK_OK && i < t->n; ++i) st = fill_knot(p, l, knots[i], t, i);
    if (st == SOAK_OK)
        st = soak_export_base_nodes(p, l, t->a, SOAK_EXPORT_KNOTS_MAX, &t->na, t->w, SOAK_EXPORT_KNOTS_MAX, &t->nw);
    if (st != SOAK_OK) return st;
    t->base = malloc((size_t)t->na * (size_t)t->nw * sizeof *t->base);
    if (!t->base) return SOAK_ERR_NOMEM;
    for (int iw = 0; st == SOAK_OK && iw < t->nw; ++iw) {
        soak_wet_input in = soak_wet_input_steady(p, t->w[iw]);
        for (int ia = 0; st == SOAK_OK && ia < t->na; ++ia) {
            soak_wet_params o;
            st = soak_wet_params_for_base(p, l, &in, (soak_rgb){t->a[ia], t->a[ia], t->a[ia]}, &o);
            if (st == SOAK_OK) t->base[iw * t->na + ia] = o.albedo;
        }
    }
    return st;
}

/* ---- writing ---------------------------------------------------------------- */

static void num(pov_out *o, double x) { out(o, "%.7g", x == 0.0 ? 0.0 : x); }

/* A string from outside (file or preset name), escaped: never raw text. */
static void text(pov_out *o, const char *s)
{
    char buf[SOAK_ESCAPE_SIZE(sizeof ((soak_export_header *)0)->materials_file)];
    if (soak_escape_povray(s, buf, sizeof buf) != SOAK_OK) o->bad = 1;
    else out(o, "%s", buf);
}

static void vec(pov_out *o, soak_rgb c)
{
    out(o, "<");
    num(o, c.r);
    out(o, ",");
    num(o, c.g);
    out(o, ",");
    num(o, c.b);
    out(o, ">");
}

/* Items per line so that the file stays readable and diffable. */
static void sep(pov_out *o, int i, int n, int per_line)
{
    if (i + 1 < n) out(o, (i + 1) % per_line ? ", " : ",\n  ");
}

static void write_header(pov_out *o, const soak_export_header *h)
{
    out(o, "// soak_materials.inc: wet-material tables for povray/soak.inc.\n");
    out(o, "// GENERATED by `soak export --target povray -o povray/soak_materials.inc`: do not edit;\n");
    out(o, "// tests/povray checks that this copy matches the preset file.\n");
    out(o, "// generator: %s; format: %s %d, povray layout %d\n", h->generator, SOAK_EXPORT_FORMAT, h->format_version,
        POV_FORMAT_VERSION);
    out(o, "// materials: ");
    text(o, h->materials_file);
    out(o, ", FNV-1a 64 %s\n", h->materials_hash);
    out(o, "// Physics: c_core/materials/include/soak/wetness.h; export contract:\n");
    out(o, "// c_core/export/include/soak/export.h; the mapping to POV-Ray's finish:\n");
    out(o, "// c_core/export/src/export_povray.c.\n");
    out(o, "#ifndef(Soak_Materials_Inc_Temp)\n#declare Soak_Materials_Inc_Temp = version;\n#version 3.7;\n");
    out(o, "#ifdef(View_POV_Include_Stack)\n  #debug \"including soak_materials.inc\\n\"\n#end\n\n");
    out(o, "#declare Soak_Data_Generator = \"%s\";\n", h->generator);
    out(o, "#declare Soak_Data_Format_Version = %d;\n", POV_FORMAT_VERSION);
    out(o, "#declare Soak_Data_Materials_File = \"");
    text(o, h->materials_file);
    out(o, "\";\n");
    out(o, "#declare Soak_Data_Materials_Hash = \"%s\";\n", h->materials_hash);
    out(o, "#declare Soak_Data_Knot_Tolerance = ");
    num(o, SOAK_EXPORT_KNOT_TOL);
    out(o, ";\n#declare Soak_Data_Base_Tolerance = ");
    num(o, SOAK_EXPORT_BASE_TOL);
    out(o, ";\n// view angles (deg from the normal) of Soak_K_View: POV-Ray's aoi pattern is 1 - angle / 180\n");
    out(o, "#declare Soak_N_View = %d;\n#declare Soak_View_Angle = array[%d] {", POV_VIEW_N, POV_VIEW_N);
    for (int k = 0; k < POV_VIEW_N; ++k) {
        num(o, view_angle_deg(k));
        out(o, k + 1 < POV_VIEW_N ? ", " : "}\n\n");
    }
}

typedef double (*preset_num)(const soak_preset *p);
static double p_kind(const soak_preset *p) { return (double)p->kind; }
static double p_tfill(const soak_preset *p) { return p->t_fill; }
static double p_sat(const soak_preset *p) { return soak_material_kind_porous(p->kind) ? p->porosity : 0.0; }
static double p_film(const soak_preset *p) { return soak_mm_from_m(p->film_thickness_m); }
static double p_sheet(const soak_preset *p) { return soak_mm_from_m(p->thickness_m); }
static double p_ior(const soak_preset *p) { return p->ior; }

static void write_presets(pov_out *o, const soak_preset_db *db)
{
    int np = soak_presets_count(db), nl = soak_presets_liquid_count(db);
    out(o, "#declare Soak_N_Presets = %d;\n#declare Soak_N_Liquids = %d;\n", np, nl);
    out(o, "// kinds: 0 porous dielectric, 1 non-porous dielectric, 2 conductor, 3 thin sheet\n");
    out(o, "#declare Soak_Preset_Names = array[%d] {\n  ", np);
    for (int i = 0; i < np; ++i) {
        out(o, "\"");
        text(o, soak_presets_at(db, i)->name);
        out(o, "\"");
        sep(o, i, np, 6);
    }
    out(o, "\n}\n");
    const char *names[] = {"Soak_Preset_Kind", "Soak_Preset_T_Fill", "Soak_Preset_Saturation",
                           "Soak_Preset_Film_Thickness_mm", "Soak_Preset_Sheet_Thickness_mm", "Soak_Preset_Ior"};
    preset_num fns[] = {p_kind, p_tfill, p_sat, p_film, p_sheet, p_ior};
    for (size_t k = 0; k < sizeof fns / sizeof fns[0]; ++k) {
        out(o, "#declare %s = array[%d] {", names[k], np);
        for (int i = 0; i < np; ++i) {
            num(o, fns[k](soak_presets_at(db, i)));
            if (i + 1 < np) out(o, ", ");
        }
        out(o, "}\n");
    }
    out(o, "#declare Soak_Liquid_Names = array[%d] {", nl);
    for (int i = 0; i < nl; ++i) {
        out(o, "\"");
        text(o, soak_presets_liquid_at(db, i)->name);
        out(o, "\"%s", i + 1 < nl ? ", " : "");
    }
    out(o, "}\n#declare Soak_Liquid_Ior = array[%d] {", nl);
    for (int i = 0; i < nl; ++i) {
        num(o, soak_presets_liquid_at(db, i)->ior);
        if (i + 1 < nl) out(o, ", ");
    }
    /* the liquid's reflectance at normal incidence in air (soak_fresnel_r0),
     * for soak.inc's wet layer over a user's texture */
    out(o, "}\n#declare Soak_Liquid_F0 = array[%d] {", nl);
    for (int i = 0; i < nl; ++i) {
        double r0 = 0.0;
        if (soak_fresnel_r0(soak_presets_liquid_at(db, i)->ior, 0.0, &r0) != SOAK_OK) r0 = 0.0;
        num(o, r0);
        if (i + 1 < nl) out(o, ", ");
    }
    out(o, "}\n\n");
}

/* soak_fill_fraction (soak/porous.h) in POV-Ray's function language, so that
 * soak.inc's animation macros derive no schedule of their own. The macro
 * returns a function of the elapsed time, which the callers compute from
 * their own start times (a T0 function, a start map). */
static void write_schedule(pov_out *o)
{
    out(o, "// The pore-filling schedule (soak_fill_fraction, c_core/models/src/porous.c): the\n");
    out(o, "// progress P of a point whose liquid started arriving Elapsed = time - t0 ago,\n");
    out(o, "// P = clamp(Elapsed / T_Fill, 0, 1), right-continuous: a step to 1 at Elapsed = 0\n");
    out(o, "// when T_Fill = 0. Soak_Fill_Progress_Fn(T_Fill) is that function of Elapsed.\n");
    out(o, "#macro Soak_Fill_Progress_Fn(T_Fill)\n");
    out(o, "  #if (T_Fill > 0)\n");
    out(o, "    #local Soak__L_Inv = 1 / T_Fill;\n");
    out(o, "    function(Soak__Elapsed) { min(max(Soak__Elapsed * Soak__L_Inv, 0), 1) }\n");
    out(o, "  #else\n");
    out(o, "    function(Soak__Elapsed) { select(Soak__Elapsed, 0, 1) }\n");
    out(o, "  #end\n");
    out(o, "#end\n\n");
}

static void write_index(pov_out *o, const char *name, const int *v, int n)
{
    out(o, "#declare %s = array[%d] {\n  ", name, n);
    for (int i = 0; i < n; ++i) {
        out(o, "%d", v[i]);
        sep(o, i, n, 16);
    }
    out(o, "\n}\n");
}

/* The per-knot tables: scalars and vectors of every table, indexed by
 * Soak_K_Start/Soak_K_Count. */
static void write_knot_tables(pov_out *o, const pov_table *tabs, int nt, int *start, int *count)
{
    int total = 0;
    for (int t = 0; t < nt; ++t) {
        start[t] = total;
        count[t] = tabs[t].n;
        total += tabs[t].n;
    }
    out(o, "// Knot tables: table t = preset * Soak_N_Liquids + liquid; knots\n");
    out(o, "// Soak_K_Start[t] .. Soak_K_Start[t] + Soak_K_Count[t] - 1; interpolate linearly in wetness.\n");
    write_index(o, "Soak_K_Start", start, nt);
    write_index(o, "Soak_K_Count", count, nt);
    for (int s = 0; s < S_COUNT; ++s) {
        out(o, "// %s\n#declare %s = array[%d] {\n  ", scal_docs[s], scal_names[s], total);
        for (int t = 0, i = 0; t < nt; ++t)
            for (int k = 0; k < tabs[t].n; ++k, ++i) {
                num(o, tabs[t].s[s][k]);
                sep(o, i, total, 8);
            }
        out(o, "\n}\n");
    }
    for (int v = 0; v < V_COUNT; ++v) {
        out(o, "// %s\n#declare %s = array[%d] {\n  ", vec_docs[v], vec_names[v], total);
        for (int t = 0, i = 0; t < nt; ++t)
            for (int k = 0; k < tabs[t].n; ++k, ++i) {
                vec(o, tabs[t].v[v][k]);
                sep(o, i, total, 3);
            }
        out(o, "\n}\n");
    }
    out(o, "// the view factor: the diffuse colour seen at Soak_View_Angle[k] over the hemispherical\n");
    out(o, "// albedo (uniform light; soak_wetness_view_factor), knot i's at Soak_K_View[i * Soak_N_View + k]\n");
    out(o, "#declare Soak_K_View = array[%d] {\n  ", total * POV_VIEW_N);
    for (int t = 0, i = 0; t < nt; ++t)
        for (int k = 0; k < tabs[t].n * POV_VIEW_N; ++k, ++i) {
            vec(o, tabs[t].view[k]);
            sep(o, i, total * POV_VIEW_N, 3);
        }
    out(o, "\n}\n");
}

/* The nodes and values of the any-base-colour tables (dry albedo x wetness).
 * idx: 4 nt ints of scratch for the index arrays. */
static void write_base_tables(pov_out *o, const pov_table *tabs, int nt, int *idx)
{
    int *node_start = idx, *value_start = idx + nt, *n_albedo = idx + 2 * nt, *n_wet = idx + 3 * nt;
    int nodes = 0, values = 0;
    for (int t = 0; t < nt; ++t) {
        node_start[t] = nodes;
        nodes += tabs[t].na + tabs[t].nw;
        value_start[t] = values;
        values += tabs[t].na * tabs[t].nw;
        n_albedo[t] = tabs[t].na;
        n_wet[t] = tabs[t].nw;
    }
    out(o, "\n// The wetness function for any base colour: per table t, dry-albedo nodes\n");
    out(o, "// Soak_B_Nodes[Soak_B_Node_Start[t] + j], j < Soak_B_N_Albedo[t], then wetness nodes\n");
    out(o, "// Soak_B_Nodes[Soak_B_Node_Start[t] + Soak_B_N_Albedo[t] + i], i < Soak_B_N_Wet[t];\n");
    out(o, "// value <r,g,b> = wet diffuse albedo of a grey dry albedo a_j at w_i (channel k: dry\n");
    out(o, "// albedo a_j in channel k) at Soak_B_Value[Soak_B_Value_Start[t] + i * Soak_B_N_Albedo[t] + j].\n");
    write_index(o, "Soak_B_Node_Start", node_start, nt);
    write_index(o, "Soak_B_N_Albedo", n_albedo, nt);
    write_index(o, "Soak_B_N_Wet", n_wet, nt);
    write_index(o, "Soak_B_Value_Start", value_start, nt);
    out(o, "#declare Soak_B_Nodes = array[%d] {\n  ", nodes);
    for (int t = 0, i = 0; t < nt; ++t) {
        for (int j = 0; j < tabs[t].na; ++j, ++i) {
            num(o, tabs[t].a[j]);
            sep(o, i, nodes, 10);
        }
        for (int j = 0; j < tabs[t].nw; ++j, ++i) {
            num(o, tabs[t].w[j]);
            sep(o, i, nodes, 10);
        }
    }
    out(o, "\n}\n#declare Soak_B_Value = array[%d] {\n  ", values);
    for (int t = 0, i = 0; t < nt; ++t)
        for (int k = 0; k < tabs[t].na * tabs[t].nw; ++k, ++i) {
            vec(o, tabs[t].base[k]);
            sep(o, i, values, 3);
        }
    out(o, "\n}\n");
}

static void write_tables(pov_out *o, pov_table *tabs, int nt)
{
    int *idx = malloc((size_t)nt * 4 * sizeof *idx);
    if (!idx) {
        o->bad = 1;
        return;
    }
    write_knot_tables(o, tabs, nt, idx, idx + nt);
    write_base_tables(o, tabs, nt, idx);
    free(idx);
}

soak_status soak_export_write_povray(const soak_preset_db *db, FILE *f, char *err, size_t errlen)
{
    soak_export_header h;
    soak_status st = soak_export_begin(db, f, err, errlen, &h);
    if (st != SOAK_OK) return st;
    int np = soak_presets_count(db), nl = soak_presets_liquid_count(db), nt = np * nl;
    pov_table *tabs = calloc((size_t)(nt > 0 ? nt : 1), sizeof *tabs);
    if (!tabs) return SOAK_ERR_NOMEM;
    for (int t = 0; st == SOAK_OK && t < nt; ++t) {
        const soak_preset *p = soak_presets_at(db, t / nl);
        const soak_liquid *l = soak_presets_liquid_at(db, t % nl);
        st = fill_table(p, l, &tabs[t]);
        if (st != SOAK_OK) snprintf(err, errlen, "preset '%s', liquid '%s': %s", p->name, l->name, soak_status_str(st));
    }
    if (st == SOAK_OK) {
        pov_out o = {f, 0};
        write_header(&o, &h);
        write_presets(&o, db);
        write_schedule(&o);
        write_tables(&o, tabs, nt);
        out(&o, "\n#version Soak_Materials_Inc_Temp;\n#end // Soak_Materials_Inc_Temp\n");
        if (o.bad) {
            snprintf(err, errlen, "write failed");
            st = SOAK_ERR_IO;
        }
    }
    for (int t = 0; t < nt; ++t) {
        free(tabs[t].base);
        free(tabs[t].view);
    }
    free(tabs);
    return st;
}
