/* Named variants of a preset (soak/preset_variant.h): porosity and film
 * thickness changed, the fields materials.json derives from the porosity
 * following it. */
#define _POSIX_C_SOURCE 200809L
#include "soak/preset_variant.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/units.h"

#include "preset_db.h"


static int valid_name(const char *s)
{
    size_t n = strlen(s);
    if (n < 1 || n >= SOAK_PRESET_NAME_MAX) return 0;
    for (; *s; ++s)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= '0' && *s <= '9') || *s == '_' || *s == '-')) return 0;
    return 1;
}

/* Porosity P on a porous preset: the rules of materials.json's sources
 * (soak/preset_variant.h); P = 0 takes the pores away altogether. */
static soak_status apply_porosity(soak_preset *p, double P, char *err, size_t errlen)
{
    if (!soak_material_kind_porous(p->kind))
        return soak_error_at(err, errlen, SOAK_ERR_ARG, p->name, NULL,
                             "porosity: kind %s has no pores to change", soak_material_kind_name(p->kind));
    const int no_pores = P == 0.0 && p->kind == SOAK_KIND_POROUS_DIELECTRIC;
    if (!no_pores && !soak_in_range(P, 1e-3, 0.95))
        return soak_error_at(err, errlen, SOAK_ERR_ARG, p->name, NULL,
                             "porosity %g must lie in [0.001, 0.95]%s", P,
                             p->kind == SOAK_KIND_POROUS_DIELECTRIC ? " or be 0 (no pores)" : " for a thin sheet");
    const double scale = (1.0 - P) / (1.0 - p->porosity);
    p->sigma_t_per_m = soak_rgb_scale(p->sigma_t_per_m, scale);
    p->porosity = P;
    p->ggx_alpha_wet = p->ggx_alpha_dry * sqrt(1.0 - P);
    if (no_pores) {
        p->kind = SOAK_KIND_NONPOROUS_DIELECTRIC;
        p->s_p = 0.0;
        p->t_fill = 0.0;
        p->phase_wet = p->phase_dry;
    }
    return soak_preset_derive(p) == SOAK_OK
               ? SOAK_OK
               : soak_error_at(err, errlen, SOAK_ERR_NUMERIC, p->name, NULL, "the dry medium cannot be derived");
}

static soak_status apply_change(soak_preset *p, const soak_preset_change *change, char *err, size_t errlen)
{
    const double film = change->film_thickness_mm;
    if (change->set_film) {
        if (!soak_in_range(film, 0.0, SOAK_VARIANT_FILM_MAX_MM))
            return soak_error_at(err, errlen, SOAK_ERR_ARG, p->name, NULL, "film_mm %g must lie in [0, %g]", film,
                                 SOAK_VARIANT_FILM_MAX_MM);
        p->film_thickness_m = soak_m_from_mm(film);
    }
    if (change->set_porosity) return apply_porosity(p, change->porosity, err, errlen);
    return SOAK_OK;
}

/* "Clay (porosity 0.2, film 0.5 mm)" */
static void describe(char *out, size_t n, const char *base, const soak_preset_change *change)
{
    char por[48] = "", film[48] = "";
    if (change->set_porosity) snprintf(por, sizeof por, "porosity %g", change->porosity);
    if (change->set_film)
        snprintf(film, sizeof film, "film %g mm", change->film_thickness_mm);
    snprintf(out, n, "%.*s (%s%s%s)", (int)(n / 2), base, por, por[0] && film[0] ? ", " : "", film);
}

static soak_status append(soak_preset_db *db, const soak_preset *v, const char *display)
{
    soak_preset *grown = realloc(db->materials, (size_t)(db->n_materials + 1) * sizeof *grown);
    if (!grown) return SOAK_ERR_NOMEM;
    db->materials = grown;
    soak_preset *slot = &db->materials[db->n_materials];
    *slot = *v;
    soak_status st = soak_preset_db_keep(db, v->name, &slot->name);
    if (st == SOAK_OK) st = soak_preset_db_keep(db, display, &slot->display_name);
    if (st == SOAK_OK) db->n_materials++;
    return st;
}

soak_status soak_presets_add_variant(soak_preset_db *db, const char *name, const char *base,
                                     const soak_preset_change *change, char *err, size_t errlen)
{
    if (err && errlen) err[0] = '\0';
    if (!db || !name || !base || !change) return SOAK_ERR_NULL;
    if (!valid_name(name))
        return soak_error_at(err, errlen, SOAK_ERR_ARG, name, NULL,
                             "a preset name has 1 to %d characters from a-z, 0-9, '_' and '-'",
                             SOAK_PRESET_NAME_MAX - 1);
    if (soak_presets_find(db, name))
        return soak_error_at(err, errlen, SOAK_ERR_ARG, name, NULL, "a preset of this name exists already");
    const soak_preset *from = soak_presets_find(db, base);
    if (!from)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, name, NULL, "no preset '%s' to vary (see soak materials)",
                             base);
    if (!change->set_porosity && !change->set_film)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, name, NULL, "nothing to change: give porosity= or film_mm=");
    soak_preset v = *from;
    v.name = name;
    v.has_measured = 0;
    soak_status st = apply_change(&v, change, err, errlen);
    if (st != SOAK_OK) return st;
    char display[SOAK_PRESET_TEXT_MAX];
    describe(display, sizeof display, from->display_name, change);
    st = append(db, &v, display);
    return st == SOAK_OK ? st : soak_error_at(err, errlen, st, name, NULL, "out of memory");
}

/* One "key=value" of a variant's text. */
static soak_status read_setting(const char *key, const char *value, soak_preset_change *change, char *err,
                                size_t errlen)
{
    const int porosity = strcmp(key, "porosity") == 0;
    if (!porosity && strcmp(key, "film_mm") != 0)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, key, NULL, "unknown setting (expected porosity or film_mm)");
    int *set = porosity ? &change->set_porosity : &change->set_film;
    double *slot = porosity ? &change->porosity : &change->film_thickness_mm;
    if (*set) return soak_error_at(err, errlen, SOAK_ERR_ARG, key, NULL, "given twice");
    char *end = NULL;
    double x = value[0] ? strtod(value, &end) : NAN;
    if (!end || *end || !isfinite(x))
        return soak_error_at(err, errlen, SOAK_ERR_ARG, key, NULL, "'%s' is not a number", value);
    *slot = x;
    *set = 1;
    return SOAK_OK;
}

static soak_status copy_name(const char *from, size_t n, char *out, const char *what, char *err, size_t errlen)
{
    if (n < 1 || n >= SOAK_PRESET_NAME_MAX)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, what, NULL, "expected 1 to %d characters",
                             SOAK_PRESET_NAME_MAX - 1);
    memcpy(out, from, n);
    out[n] = '\0';
    return SOAK_OK;
}

soak_status soak_preset_variant_parse(const char *text, char *name, char *base, soak_preset_change *change,
                                      char *err, size_t errlen)
{
    if (err && errlen) err[0] = '\0';
    if (!text || !name || !base || !change) return SOAK_ERR_NULL;
    memset(change, 0, sizeof *change);
    const char *eq = strchr(text, '='), *comma = eq ? strchr(eq, ',') : NULL;
    if (!eq || !comma)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, text, NULL,
                             "expected NAME=BASE,porosity=P and/or film_mm=H, e.g. clay_p20=clay,porosity=0.2");
    soak_status st = copy_name(text, (size_t)(eq - text), name, "NAME", err, errlen);
    if (st == SOAK_OK) st = copy_name(eq + 1, (size_t)(comma - eq - 1), base, "BASE", err, errlen);
    for (const char *s = comma + 1; st == SOAK_OK; s = comma + 1) {
        char item[64] = "";
        comma = strchr(s, ',');
        size_t n = comma ? (size_t)(comma - s) : strlen(s);
        char *sep = n < sizeof item ? (memcpy(item, s, n), strchr(item, '=')) : NULL;
        if (!sep || sep == item)
            return soak_error_at(err, errlen, SOAK_ERR_ARG, text, NULL, "expected key=value after ','");
        *sep = '\0';
        st = read_setting(item, sep + 1, change, err, errlen);
        if (!comma) break;
    }
    return st;
}
