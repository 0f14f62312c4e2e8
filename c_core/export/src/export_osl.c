/* soak export --target osl | osl-legacy | osl-sheet | osl-wetmap |
 * osl-math: self-contained OSL shaders for Cycles (osl/README.md) and their
 * arithmetic as a header. The shaders carry the core's tables as constant
 * arrays and evaluate them with soak_wet_math.h, inlined from the one copy
 * the C tests compile (c_core/export/src/soak_wet_math.h; CMake generates
 * soak_wet_math_text.h from it). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "export_osl_tables.h"
#include "soak/export_escape.h"
#include "soak/sheet.h"
#include "soak_wet_math_text.h"

/* ---- growable lists ------------------------------------------------------ */

static int fl_push(soak_float_list *l, double x)
{
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 256;
        float *v = realloc(l->v, (size_t)cap * sizeof *v);
        if (!v) return 0;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = (float)x;
    return 1;
}

static int il_push(soak_int_list *l, int x)
{
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 64;
        int *v = realloc(l->v, (size_t)cap * sizeof *v);
        if (!v) return 0;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = x;
    return 1;
}

static int fl_rgb(soak_float_list *l, soak_rgb c) { return fl_push(l, c.r) && fl_push(l, c.g) && fl_push(l, c.b); }

void soak_osl_tables_free(soak_osl_tables *t)
{
    if (!t) return;
    soak_float_list *f[] = {&t->kw, &t->ka, &t->kc, &t->kr, &t->kt, &t->kv, &t->ks, &t->kf, &t->ior, &t->ba, &t->bw, &t->bg};
    soak_int_list *i[] = {&t->preset, &t->kind, &t->k_off, &t->k_n, &t->ba_off, &t->ba_n, &t->bw_off, &t->bw_n, &t->bg_off};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; ++k) free(f[k]->v);
    for (size_t k = 0; k < sizeof i / sizeof i[0]; ++k) free(i[k]->v);
    memset(t, 0, sizeof *t);
}

/* ---- tables ---------------------------------------------------------------- */

/* Floor of the tabulated sheet transmittance (its logarithm is stored). */
#define SHEET_T_MIN 1e-6

static soak_status add_knots(soak_osl_tables *t, const soak_preset *p, const soak_liquid *l)
{
    double knots[SOAK_EXPORT_KNOTS_MAX];
    int n = 0;
    soak_status st = soak_export_knots(p, l, -1.0, knots, SOAK_EXPORT_KNOTS_MAX, &n);
    if (st != SOAK_OK) return st;
    if (!il_push(&t->k_off, t->kw.n) || !il_push(&t->k_n, n)) return SOAK_ERR_NOMEM;
    for (int i = 0; i < n; ++i) {
        soak_wet_input in = soak_wet_input_steady(p, knots[i]);
        soak_wet_params w;
        soak_rgb sheet = {0, 0, 0}, view[SOAK_EXPORT_VIEW_N];
        st = soak_wetness_eval(p, l, &in, &w);
        if (st == SOAK_OK && p->kind == SOAK_KIND_THIN_SHEET) st = soak_sheet_transmittance(&w, p->thickness_m, p->ior, &sheet);
        if (st == SOAK_OK) st = soak_export_view_factors(p, l, &w, view);
        if (st != SOAK_OK) return st;
        for (int v = 0; v < SOAK_EXPORT_VIEW_N; ++v)
            if (!fl_rgb(&t->kv, view[v])) return SOAK_ERR_NOMEM;
        double interface = soak_wet_interface_area(&w);
        soak_rgb log_sheet = {log(fmax(sheet.r, SHEET_T_MIN)), log(fmax(sheet.g, SHEET_T_MIN)),
                              log(fmax(sheet.b, SHEET_T_MIN))};
        if (!fl_push(&t->kw, knots[i]) || !fl_rgb(&t->ka, w.albedo) || !fl_push(&t->kc, interface) ||
            !fl_push(&t->kr, sqrt(w.ggx_alpha)) || !fl_rgb(&t->kt, log_sheet) ||
            !fl_push(&t->ks, p->kind == SOAK_KIND_CONDUCTOR || p->kind == SOAK_KIND_THIN_SHEET ? 0.0 : w.specular_weight) ||
            !fl_push(&t->kf, w.film_coverage))
            return SOAK_ERR_NOMEM;
    }
    return SOAK_OK;
}

static soak_status add_base(soak_osl_tables *t, const soak_preset *p, const soak_liquid *l)
{
    double a[SOAK_EXPORT_KNOTS_MAX], w[SOAK_EXPORT_KNOTS_MAX];
    int na = 0, nw = 0;
    soak_status st = soak_export_base_nodes(p, l, a, SOAK_EXPORT_KNOTS_MAX, &na, w, SOAK_EXPORT_KNOTS_MAX, &nw);
    if (st != SOAK_OK) return st;
    if (!il_push(&t->ba_off, t->ba.n) || !il_push(&t->ba_n, na) || !il_push(&t->bw_off, t->bw.n) ||
        !il_push(&t->bw_n, nw))
        return SOAK_ERR_NOMEM;
    for (int i = 0; i < na; ++i)
        if (!fl_push(&t->ba, a[i])) return SOAK_ERR_NOMEM;
    for (int i = 0; i < nw; ++i)
        if (!fl_push(&t->bw, w[i])) return SOAK_ERR_NOMEM;
    double *grid = malloc((size_t)na * (size_t)nw * 3 * sizeof *grid);
    if (!grid) return SOAK_ERR_NOMEM;
    for (int iw = 0; st == SOAK_OK && iw < nw; ++iw) {
        soak_wet_input in = soak_wet_input_steady(p, w[iw]);
        for (int ia = 0; st == SOAK_OK && ia < na; ++ia) {
            soak_wet_params o;
            st = soak_wet_params_for_base(p, l, &in, (soak_rgb){a[ia], a[ia], a[ia]}, &o);
            for (int c = 0; st == SOAK_OK && c < 3; ++c) grid[((size_t)c * nw + iw) * na + ia] = soak_rgb_at(o.albedo, c);
        }
    }
    for (int c = 0; st == SOAK_OK && c < 3; ++c) {
        if (!il_push(&t->bg_off, t->bg.n)) st = SOAK_ERR_NOMEM;
        for (int i = 0; st == SOAK_OK && i < na * nw; ++i)
            if (!fl_push(&t->bg, grid[(size_t)c * nw * na + i])) st = SOAK_ERR_NOMEM;
    }
    free(grid);
    return st;
}

soak_status soak_osl_tables_build(const soak_preset_db *db, int sheets_only, soak_osl_tables *t)
{
    if (!db || !t) return SOAK_ERR_NULL;
    memset(t, 0, sizeof *t);
    t->n_liquids = soak_presets_liquid_count(db);
    soak_status st = SOAK_OK;
    for (int i = 0; st == SOAK_OK && i < soak_presets_count(db); ++i) {
        const soak_preset *p = soak_presets_at(db, i);
        if (sheets_only && p->kind != SOAK_KIND_THIN_SHEET) continue;
        int kind = p->kind == SOAK_KIND_CONDUCTOR ? 1 : (p->kind == SOAK_KIND_THIN_SHEET ? 2 : 0);
        t->n_presets++;
        if (!il_push(&t->kind, kind) || !il_push(&t->preset, i) || !fl_push(&t->ior, kind == 1 ? 0.0 : p->ior))
            st = SOAK_ERR_NOMEM;
        for (int j = 0; st == SOAK_OK && j < t->n_liquids; ++j) {
            const soak_liquid *l = soak_presets_liquid_at(db, j);
            st = add_knots(t, p, l);
            if (st == SOAK_OK) st = add_base(t, p, l);
        }
    }
    if (st != SOAK_OK) soak_osl_tables_free(t);
    return st;
}

/* ---- writing ---------------------------------------------------------------- */

static void put_floats(FILE *out, const char *name, const soak_float_list *l)
{
    fprintf(out, "    float %s[%d] = {", name, l->n);
    for (int i = 0; i < l->n; ++i) fprintf(out, "%s%.7g", i % 8 ? ", " : (i ? ",\n        " : "\n        "), l->v[i]);
    fprintf(out, "};\n");
}

static void put_ints(FILE *out, const char *name, const soak_int_list *l)
{
    fprintf(out, "    int %s[%d] = {", name, l->n);
    for (int i = 0; i < l->n; ++i) fprintf(out, "%s%d", i ? ", " : "", l->v[i]);
    fprintf(out, "};\n");
}

/* A string from outside (file or preset name), escaped: never raw source. */
static const char *osl_text(const char *s, char *buf, size_t cap)
{
    return soak_escape_osl(s, buf, cap) == SOAK_OK ? buf : "?";
}

static void put_header(FILE *out, const soak_export_header *h, const char *what)
{
    char file[SOAK_ESCAPE_SIZE(sizeof h->materials_file)];
    fprintf(out,
            "// %s\n"
            "// GENERATED by `soak export` (%s, format %d) from %s (FNV-1a %s): do not edit;\n"
            "// regenerate with the command in osl/README.md. Self-contained (no #include):\n"
            "// Blender compiles Internal text blocks from a temporary folder.\n\n"
            "#define SOAK_OSL 1\n",
            what, h->generator, h->format_version, osl_text(h->materials_file, file, sizeof file), h->materials_hash);
    fputs(SOAK_WET_MATH_TEXT, out);
    fputc('\n', out);
}

static const char *preset_name(const soak_preset_db *db, const soak_osl_tables *t, int i)
{
    return soak_presets_at(db, t->preset.v[i])->name;
}

static void put_name_options(FILE *out, const soak_preset_db *db, const soak_osl_tables *t, int liquids)
{
    int n = liquids ? t->n_liquids : t->n_presets;
    char name[SOAK_ESCAPE_SIZE(SOAK_PRESET_NAME_MAX)];
    for (int i = 0; i < n; ++i)
        fprintf(out, "%s%s", i ? "|" : "",
                osl_text(liquids ? soak_presets_liquid_at(db, i)->name : preset_name(db, t, i), name, sizeof name));
}

static void put_name_lookup(FILE *out, const soak_preset_db *db, const soak_osl_tables *t, int liquids,
                            const char *shader)
{
    const char *param = liquids ? "Liquid" : "Preset", *var = liquids ? "li" : "pi";
    int n = liquids ? t->n_liquids : t->n_presets;
    fprintf(out, "    int %s = -1;\n", var);
    char name[SOAK_ESCAPE_SIZE(SOAK_PRESET_NAME_MAX)];
    for (int i = 0; i < n; ++i)
        fprintf(out, "    if (%s == \"%s\") %s = %d;\n", param,
                osl_text(liquids ? soak_presets_liquid_at(db, i)->name : preset_name(db, t, i), name, sizeof name),
                var, i);
    fprintf(out, "    if (%s < 0) {\n        warning(\"%s: unknown %s \\\"%%s\\\", using the first\", %s);\n"
                 "        %s = 0;\n    }\n",
            var, shader, param, param, var);
}

static void put_liquid_iors(FILE *out, const soak_preset_db *db)
{
    soak_float_list l = {0};
    for (int i = 0; i < soak_presets_liquid_count(db); ++i) fl_push(&l, soak_presets_liquid_at(db, i)->ior);
    put_floats(out, "LIQUID_IOR", &l);
    free(l.v);
}

/* The three wet-surface shaders differ in their presets, sockets and the
 * closure of metals; the tables and the lookups are shared. */
typedef enum { OSL_SURFACE, OSL_SURFACE_LEGACY, OSL_SHEET } osl_variant;

static const char *shader_name(osl_variant v)
{
    return v == OSL_SHEET ? "soak_wet_sheet" : (v == OSL_SURFACE ? "soak_wet_surface" : "soak_wet_surface_legacy");
}

static void put_signature(FILE *out, const soak_preset_db *db, const soak_osl_tables *t, osl_variant v)
{
    char name[SOAK_ESCAPE_SIZE(SOAK_PRESET_NAME_MAX)];
    fprintf(out, "shader %s(\n    string Preset = \"%s\" [[ string widget = \"popup\", string options = \"",
            shader_name(v), osl_text(preset_name(db, t, 0), name, sizeof name));
    put_name_options(out, db, t, 0);
    fprintf(out, "\" ]],\n    string Liquid = \"%s\" [[ string widget = \"popup\", string options = \"",
            osl_text(soak_presets_liquid_at(db, 0)->name, name, sizeof name));
    put_name_options(out, db, t, 1);
    fputs("\" ]],\n"
          "    float Wetness = 1.0 [[ float min = 0, float max = 1 ]],\n"
          "    float Time = 1.0,\n"
          "    float T0 = 0.0,\n"
          "    float FillTime = 0.0 [[ float min = 0 ]],\n"
          "    int UseBaseColor = 0 [[ string widget = \"checkBox\" ]],\n"
          "    color BaseColor = color(0.5),\n",
          out);
    if (v != OSL_SHEET) fputs("    float Puddle = 0.0 [[ float min = 0, float max = 1 ]],\n", out);
    fputs("    normal Normal = N,\n"
          "    output closure color BSDF = 0,\n"
          "    output color WetColor = 0,\n",
          out);
    if (v == OSL_SHEET) fputs("    output color Transmittance = 0,\n", out);
    fputs("    output float Coverage = 0,\n"
          "    output float Roughness = 0)\n"
          "{\n",
          out);
}

static void put_tables(FILE *out, const soak_preset_db *db, const soak_osl_tables *t)
{
    put_ints(out, "KIND", &t->kind);
    put_floats(out, "KW", &t->kw);
    put_floats(out, "KA", &t->ka);
    put_floats(out, "KC", &t->kc);
    put_floats(out, "KR", &t->kr);
    put_floats(out, "KT", &t->kt);
    put_floats(out, "KV", &t->kv);
    put_floats(out, "KS", &t->ks);
    put_floats(out, "KF", &t->kf);
    put_floats(out, "MAT_IOR", &t->ior);
    put_ints(out, "K_OFF", &t->k_off);
    put_ints(out, "K_N", &t->k_n);
    put_floats(out, "BA", &t->ba);
    put_floats(out, "BW", &t->bw);
    put_floats(out, "BG", &t->bg);
    put_ints(out, "BA_OFF", &t->ba_off);
    put_ints(out, "BA_N", &t->ba_n);
    put_ints(out, "BW_OFF", &t->bw_off);
    put_ints(out, "BW_N", &t->bw_n);
    put_ints(out, "BG_OFF", &t->bg_off);
    put_liquid_iors(out, db);
}

/* The liquid L, the wet colour, the interface area and the roughness. */
static void put_lookup(FILE *out, const soak_osl_tables *t, osl_variant v)
{
    fprintf(out, "    int k = pi * %d + li;\n", t->n_liquids);
    if (v == OSL_SHEET)
        fputs("    float L = soak_delivered(Wetness, Time, T0, FillTime);\n", out);
    else
        fputs("    // a puddle floods the surface: at least that much liquid, up to a full film\n"
              "    float L = max(soak_delivered(Wetness, Time, T0, FillTime), soak_clamp01(Puddle));\n",
              out);
    fputs("    for (int c = 0; c < 3; c += 1) {\n"
          "        if (UseBaseColor)\n"
          "            WetColor[c] = soak_base_lookup(BA, BA_OFF[k], BA_N[k], BW, BW_OFF[k], BW_N[k], BG, BG_OFF[3 * k + c],\n"
          "                                           soak_clamp01(BaseColor[c]), L);\n"
          "        else\n"
          "            WetColor[c] = soak_interp(KW, K_OFF[k], K_N[k], L, KA, 3 * K_OFF[k] + c, 3);\n"
          "    }\n"
          "    Coverage = soak_interp(KW, K_OFF[k], K_N[k], L, KC, K_OFF[k], 1);\n"
          "    Roughness = soak_interp(KW, K_OFF[k], K_N[k], L, KR, K_OFF[k], 1);\n"
          "    // Cycles' reflection() is a perfect mirror without Fresnel: weight it here\n"
          "    float cos_view = abs(dot(normalize(I), normalize(Normal)));\n"
          "    float mirror = Coverage * soak_fresnel(cos_view, LIQUID_IOR[li]);\n"
          "    // the liquid interface's transmission towards the viewer (the light's side a\n"
          "    // diffuse closure cannot follow): the weight of the diffuse closure\n"
          "    color View = 1;\n"
          "    for (int c = 0; c < 3; c += 1)\n"
          "        View[c] = soak_view_lookup(KW, K_OFF[k], K_N[k], L, KV, 3 * SOAK_VIEW_N * K_OFF[k] + c, cos_view);\n",
          out);
}

static void put_closure(FILE *out, osl_variant v)
{
    if (v == OSL_SHEET) {
        fputs("    for (int c = 0; c < 3; c += 1) Transmittance[c] = soak_interp_log(KW, K_OFF[k], K_N[k], L, KT, 3 * K_OFF[k] + c, 3);\n"
              "    BSDF = WetColor * View * diffuse(Normal) + Transmittance * translucent(Normal) + mirror * reflection(Normal);\n"
              "}\n",
              out);
        return;
    }
    fputs("    float alpha = max(Roughness * Roughness, 1e-4);\n"
          "    if (KIND[pi] == 1) {\n"
          "        // metal under the film: WetColor is its normal reflectance through the liquid\n",
          out);
    if (v == OSL_SURFACE)
        fputs("        BSDF = WetColor * microfacet(\"ggx\", Normal, alpha, 0.0, 0) + mirror * reflection(Normal);\n", out);
    else
        fputs("        BSDF = WetColor * microfacet_ggx(Normal, alpha) + mirror * reflection(Normal);\n", out);
    fputs("    } else {\n"
          "        // the diffuse albedo under the liquid interface (porous darkening and the\n"
          "        // interface's total internal reflection are in WetColor), the interface's\n"
          "        // Fresnel mirror over its area, and the material's own rough interface where\n"
          "        // no film covers it: the grains stay in air over 1 - c, the pore water has no\n"
          "        // grain under it (soak/wet_specular.h point 1: weight ks (1 - c), GGX alpha,\n"
          "        // Fresnel of its index; the closure has none of its own, taken at the view)\n"
          "        float lobe = soak_interp(KW, K_OFF[k], K_N[k], L, KS, K_OFF[k], 1)\n"
          "                     * (1 - soak_interp(KW, K_OFF[k], K_N[k], L, KF, K_OFF[k], 1))\n"
          "                     * soak_fresnel(cos_view, MAT_IOR[pi]);\n"
          "        BSDF = WetColor * View * diffuse(Normal) + mirror * reflection(Normal);\n",
          out);
    if (v == OSL_SURFACE)
        fputs("        if (lobe > 0) BSDF += lobe * microfacet(\"ggx\", Normal, alpha, 0.0, 0);\n", out);
    else
        fputs("        if (lobe > 0) BSDF += lobe * microfacet_ggx(Normal, alpha);\n", out);
    fputs(
          "        if (KIND[pi] == 2) {\n"
          "            color T = 0;\n"
          "            for (int c = 0; c < 3; c += 1) T[c] = soak_interp_log(KW, K_OFF[k], K_N[k], L, KT, 3 * K_OFF[k] + c, 3);\n"
          "            BSDF += T * translucent(Normal);\n"
          "        }\n"
          "    }\n"
          "}\n",
          out);
}

static const char *const osl_titles[] = {
    "soak_wet_surface.osl: a wet surface for Cycles, Blender 3.4 to 4.x.",
    "soak_wet_surface_legacy.osl: a wet surface for Cycles, Blender 2.80 to 3.4.",
    "soak_wet_sheet.osl: a wet thin sheet (paper, cloth) for Cycles, Blender 2.80 to 4.x.",
};

static const char *const osl_closure_notes[] = {
    "// Closures: diffuse, translucent, reflection and the generic microfacet of\n"
    "// stdosl.h, all registered by Cycles from 3.4 (kernel/osl/closures.cpp) to\n"
    "// 4.x (kernel/osl/closures_template.h). Blender 2.80-3.3: use\n"
    "// soak_wet_surface_legacy.osl. reflection() has no Fresnel term in Cycles:\n"
    "// soak_fresnel weights it.\n\n",
    "// Closures: diffuse, translucent, reflection and Cycles' microfacet_ggx\n"
    "// (declared here as stdcycles.h of Blender 2.80-3.4 does; registered in\n"
    "// kernel/osl/osl_closures.cpp and, from 3.2, closures.cpp). Blender 4.x no\n"
    "// longer has microfacet_ggx: use soak_wet_surface.osl there.\n\n"
    "closure color microfacet_ggx(normal N, float ag) [[ int builtin = 1 ]];\n\n",
    "// Translucent when wet: the front is the core's wet albedo (diffuse), the\n"
    "// back lets the core's two-flux transmittance (faces included) through.\n"
    "// Closures: diffuse, translucent, reflection (every Cycles 2.80-4.x).\n"
    "// With UseBaseColor the front colour is yours; the transmittance stays the\n"
    "// preset's.\n\n",
};

static soak_status write_surface(const soak_preset_db *db, FILE *out, char *err, size_t errlen, osl_variant v)
{
    soak_export_header h;
    soak_status st = soak_export_begin(db, out, err, errlen, &h);
    if (st != SOAK_OK) return st;
    soak_osl_tables t;
    st = soak_osl_tables_build(db, v == OSL_SHEET, &t);
    if (st == SOAK_OK && t.n_presets == 0) {
        soak_osl_tables_free(&t);
        snprintf(err, errlen, "%s holds no %s preset: this target needs at least one", h.materials_file,
                 v == OSL_SHEET ? "thin_sheet" : "surface (non-thin_sheet)");
        return SOAK_ERR_ARG;
    }
    if (st != SOAK_OK) {
        snprintf(err, errlen, "building the OSL tables failed: %s", soak_status_str(st));
        return st;
    }
    put_header(out, &h, osl_titles[v]);
    fputs("// Inputs: a preset (its class: porosity, phase change, film) and liquid,\n"
          "// the wetness and the pore-filling schedule (Time, T0, FillTime: see\n"
          "// soak_delivered), an optional base colour of the user's own texture\n"
          "// (UseBaseColor 1: the core's wetness function for any colour)",
          out);
    fputs(v == OSL_SHEET ? ".\n" : ", a puddle\n// level that floods the surface with a film.\n", out);
    fputs("// Outputs: the closure and the parameters it used.\n", out);
    fputs(osl_closure_notes[v], out);
    put_signature(out, db, &t, v);
    put_tables(out, db, &t);
    put_name_lookup(out, db, &t, 0, shader_name(v));
    put_name_lookup(out, db, &t, 1, shader_name(v));
    put_lookup(out, &t, v);
    put_closure(out, v);
    soak_osl_tables_free(&t);
    return ferror(out) ? SOAK_ERR_IO : SOAK_OK;
}

soak_status soak_export_write_osl(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    return write_surface(db, out, err, errlen, OSL_SURFACE);
}

soak_status soak_export_write_osl_legacy(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    return write_surface(db, out, err, errlen, OSL_SURFACE_LEGACY);
}

soak_status soak_export_write_osl_sheet(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    return write_surface(db, out, err, errlen, OSL_SHEET);
}

soak_status soak_export_write_osl_wetmap(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    soak_export_header h;
    soak_status st = soak_export_begin(db, out, err, errlen, &h);
    if (st != SOAK_OK) return st;
    put_header(out, &h, "soak_wetmap.osl: wetness from a wet map and the pore schedule (Blender 2.80 to 4.x).");
    fputs("// WetMap: a start-time map from `soak bake drying --start-map` (value 1 - t0 on\n"
          "// wet texels, 0 where dry), converted to .tx by maketx (or written as .tx by\n"
          "// soak bake). Drying 1: the liquid leaves over FillTime from t0 (the baker's\n"
          "// --mode schedule); Drying 0: it arrives over FillTime from t0. Plug Wetness\n"
          "// into soak_wet_surface's Wetness (with its Time = 1, FillTime = 0).\n"
          "// RippleFile: a `soak bake ripples -o ripples.%04d.tx` flipbook's path up to its\n"
          "// frame number (ripples.), RippleExtension the rest (.tx); RGB = (n + 1) / 2 in\n"
          "// tangent space, v up. Frame Frame modulo LoopFrames is read,\n"
          "// RippleRepeat tiles across the UV square; RippleNormal bends N by it where\n"
          "// Wetness reaches PuddleLevel (standing water) and is N elsewhere. Tangent: the\n"
          "// UV map's tangent (Blender: a Tangent node, UV Map).\n\n"
          "shader soak_wetmap(\n"
          "    string WetMap = \"\",\n"
          "    int Drying = 1 [[ string widget = \"checkBox\" ]],\n"
          "    float Time = 0.0,\n"
          "    float FillTime = 0.2 [[ float min = 0 ]],\n"
          "    float Amount = 1.0 [[ float min = 0, float max = 1 ]],\n"
          "    point UV = point(u, v, 0),\n"
          "    string RippleFile = \"\",\n"
          "    string RippleExtension = \".tx\",\n"
          "    int Frame = 0,\n"
          "    int LoopFrames = 64 [[ int min = 1 ]],\n"
          "    float RippleRepeat = 1.0 [[ float min = 0 ]],\n"
          "    float PuddleLevel = 1.0 [[ float min = 0, float max = 1 ]],\n"
          "    vector Tangent = dPdu,\n"
          "    output float Wetness = 0,\n"
          "    output normal RippleNormal = N)\n"
          "{\n"
          "    float start = 1.0;\n"
          "    // clamp: a wet map covers the UV square; the default (black) would dry its border\n"
          "    if (WetMap != \"\") start = texture(WetMap, UV[0], 1.0 - UV[1], \"wrap\", \"clamp\");\n"
          "    if (start <= 0.0) {\n"
          "        Wetness = 0.0;\n"
          "    } else {\n"
          "        float t0 = 1.0 - soak_clamp01(start);\n"
          "        Wetness = Drying ? soak_remaining(Amount, Time, t0, FillTime) : soak_delivered(Amount, Time, t0, FillTime);\n"
          "    }\n"
          "    // 1e-4: a texel at the puddle level floods despite float rounding (as the Blender add-on)\n"
          "    if (RippleFile != \"\" && Wetness >= PuddleLevel - 1e-4) {\n"
          "        int loop = LoopFrames > 1 ? LoopFrames : 1;\n"
          "        int f = Frame % loop;\n"
          "        if (f < 0) f += loop;\n"
          "        string file = format(\"%s%04d%s\", RippleFile, f, RippleExtension);\n"
          "        color c = texture(file, UV[0] * RippleRepeat, 1.0 - UV[1] * RippleRepeat,\n"
          "                          \"wrap\", \"periodic\", \"interp\", \"linear\");  // as Blender's Linear image node\n"
          "        vector t = normalize(Tangent - dot(Tangent, N) * N);\n"
          "        vector b = cross(N, t);\n"
          "        RippleNormal = normalize((2 * c[0] - 1) * t + (2 * c[1] - 1) * b + (2 * c[2] - 1) * N);\n"
          "    }\n"
          "}\n",
          out);
    return ferror(out) ? SOAK_ERR_IO : SOAK_OK;
}

soak_status soak_export_write_osl_math(const soak_preset_db *db, FILE *out, char *err, size_t errlen)
{
    if (!db || !out || !err) return SOAK_ERR_NULL;
    fprintf(out,
            "/* GENERATED by `soak export --target osl-math -o osl/soak_wet_math.h` (%s) from\n"
            " * c_core/export/src/soak_wet_math.h: do not edit; tests/cli/osl_shaders.sh\n"
            " * fails when this copy is stale. The shipped shaders inline the same text. */\n",
            SOAK_EXPORT_GENERATOR);
    fputs(SOAK_WET_MATH_TEXT, out);
    if (ferror(out)) {
        snprintf(err, errlen, "write failed");
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}
