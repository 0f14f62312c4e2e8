/* A preset's BSDFs at the levels of the liquid amount (scene_levels.h), set
 * up once per render, and the level a hit is shaded with. Between levels
 * t_i <= x < t_i+1 of the object's wetness x, level i + 1 is drawn with
 * probability (x - t_i) / (t_i+1 - t_i): the expected BSDF is the linear
 * interpolation of the two levels' BSDFs (their dry/wet/pore mixtures) in
 * x, the same one-sample choice as the dry/wet draw (render_surface.c). */
#include <stdio.h>
#include <stdlib.h>

#include "render_levels.h"
#include "render_bsdfs.h"
#include "scene_levels.h"

soak_status rt_levels_setup(const soak_scene *s, int trace_films, rt_levels *out, char *err, size_t errlen)
{
    for (int i = 0; i < s->n_materials; ++i) {
        const soak_material *m = &s->materials[i];
        const soak_material_levels *L = m->levels;
        out[i].n = 0;
        out[i].bsdf = NULL;
        if (!L || L->n == 0 || m->type != SOAK_MAT_WET) continue;
        out[i].bsdf = calloc((size_t)L->n, sizeof *out[i].bsdf);
        if (!out[i].bsdf) return SOAK_ERR_NOMEM;
        for (int k = 0; k < L->n; ++k) {
            soak_status st = rt_material_bsdf_setup(&L->view[k], trace_films, &out[i].bsdf[k]);
            if (st != SOAK_OK) {
                if (err && errlen)
                    snprintf(err, errlen, "material '%s' at object wetness %g: BSDF set-up failed (%s)", m->name,
                             L->t[k], soak_status_str(st));
                return st;
            }
        }
        out[i].n = L->n;
    }
    return SOAK_OK;
}

void rt_levels_free(rt_levels *levels, int n_materials)
{
    if (!levels) return;
    for (int i = 0; i < n_materials; ++i) free(levels[i].bsdf);
    free(levels);
}

double rt_level_at(rt_thread *t, const soak_object *obj, const soak_hit *hit, const soak_material **m,
                   const rt_material_bsdf **mb)
{
    double x = soak_scene_wetness(obj, hit->p, hit->u, hit->v);
    const rt_levels *lv = t->ctx->levels ? &t->ctx->levels[obj->material] : NULL;
    if (!lv || lv->n == 0) return x * (*m)->film_coverage;
    const soak_material_levels *L = (*m)->levels;
    double f;
    int i = scene_levels_find(L, x, &f);
    if (f >= 1.0 || (f > 0 && rt_rand(t) < f)) ++i;
    int film_over = L->recipe.film_over;
    *m = &L->view[i];
    *mb = &lv->bsdf[i];
    /* the chain's film is that of the level's liquid amount; a "film_over"
     * lies where the object is wet, as without levels */
    return film_over ? x * (*m)->film_coverage : (*m)->film_coverage;
}
