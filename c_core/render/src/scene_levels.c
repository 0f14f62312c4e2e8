/* A preset's states at the wetness of each point (scene_levels.h). */
#include "scene_levels.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void scene_levels_free(soak_material *m)
{
    if (!m->levels) return;
    free(m->levels->t);
    free(m->levels->view);
    free(m->levels);
    m->levels = NULL;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The object wetnesses material mi is seen at, into t (room for
 * SOAK_LEVELS_GRID + 2 + n_objects), sorted and distinct; returns how many
 * (0: only the constant 1, the material's own state). kink: the object
 * wetness at which the pores are full (outside (0, 1): none). */
static int level_knots(const soak_scene *s, int mi, double kink, double *t)
{
    int n = 0, varies = 0, other = 0;
    for (int i = 0; i < s->n_objects; ++i) {
        const soak_object *o = &s->objects[i];
        if (o->material != mi) continue;
        if (o->wetness.type != SOAK_WETNESS_CONSTANT) varies = 1;
        else if (o->wetness.value != 1.0) t[n++] = o->wetness.value, other = 1;
    }
    if (!varies && !other) return 0;
    if (varies) {
        for (int i = 0; i < SOAK_LEVELS_GRID; ++i) t[n++] = (double)i / (SOAK_LEVELS_GRID - 1);
        if (kink > 0 && kink < 1) t[n++] = kink;
    }
    t[n++] = 1.0;
    qsort(t, (size_t)n, sizeof *t, by_value);
    int k = 0;
    for (int i = 0; i < n; ++i)
        if (k == 0 || t[i] > t[k - 1]) t[k++] = t[i];
    return k;
}

static soak_status build_views(scene_ctx *c, const char *name, soak_material *m, const soak_preset *p,
                               const soak_liquid *liq, int n, const double *t)
{
    soak_material_levels *L = m->levels;
    L->t = malloc((size_t)n * sizeof *L->t);
    L->view = malloc((size_t)n * sizeof *L->view);
    if (!L->t || !L->view) return SOAK_ERR_NOMEM;
    for (int i = 0; i < n; ++i) {
        L->t[i] = t[i];
        L->view[i] = *m;
        L->view[i].levels = NULL;
        /* at object wetness 1 the level is the material as parsed: the
         * same chain at the same liquid amount, not run again */
        soak_status st =
            t[i] == 1.0 ? SOAK_OK : scene_preset_view(p, liq, &L->recipe, t[i] * L->recipe.wetness, &L->view[i]);
        if (st != SOAK_OK) {
            char path[128];
            snprintf(path, sizeof path, "materials.%s", name);
            return sj_fail(c, st, path, "the preset at liquid amount %g (object wetness %g): %s",
                           t[i] * L->recipe.wetness, t[i], soak_status_str(st));
        }
    }
    L->n = n;
    return SOAK_OK;
}

static soak_status material_levels(scene_ctx *c, soak_scene *s, int mi, const soak_preset_db *db)
{
    soak_material *m = &s->materials[mi];
    const scene_preset_recipe *rec = &m->levels->recipe;
    const soak_preset *p = soak_presets_find(db, rec->name);
    const soak_liquid *liq = soak_presets_find_liquid(db, rec->liquid);
    if (!p || !liq) return SOAK_ERR_NOT_FOUND; /* found when the material was parsed */
    double *t = malloc((size_t)(SOAK_LEVELS_GRID + 2 + s->n_objects) * sizeof *t);
    if (!t) return SOAK_ERR_NOMEM;
    /* a dry material is the same at every level; the object wetness where
     * the pores are full (L = w_sat) is a bend of every quantity in L */
    int n = rec->wetness > 0 ? level_knots(s, mi, rec->saturation / rec->wetness, t) : 0;
    soak_status st = n > 0 ? build_views(c, m->name, m, p, liq, n, t) : SOAK_OK;
    free(t);
    return st;
}

soak_status scene_levels_build(scene_ctx *c, soak_scene *s)
{
    int needed = 0;
    for (int i = 0; i < s->n_materials; ++i)
        needed |= s->materials[i].levels != NULL && s->materials[i].type == SOAK_MAT_WET;
    if (!needed) return SOAK_OK;
    const soak_preset_db *db = NULL; /* loaded by the preset materials */
    soak_status st = scene_presets_db(c, "materials", &db);
    for (int i = 0; i < s->n_materials && st == SOAK_OK; ++i)
        if (s->materials[i].levels && s->materials[i].type == SOAK_MAT_WET) st = material_levels(c, s, i, db);
    return st;
}

int scene_levels_find(const soak_material_levels *L, double x, double *frac)
{
    int lo = 0, hi = L->n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (L->t[mid] <= x) lo = mid;
        else hi = mid;
    }
    double span = L->t[hi] - L->t[lo];
    double f = span > 0 ? (x - L->t[lo]) / span : 0.0;
    *frac = f < 0 ? 0 : (f > 1 ? 1 : f);
    return lo;
}
