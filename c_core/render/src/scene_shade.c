/* What the renderer asks of a scene per hit (soak/scene.h): an object's
 * wetness at a point, and the model and parameters a material is drawn
 * with. Nothing here parses or allocates. */
#include <math.h>
#include <string.h>

#include "soak/scene.h"

double soak_scene_wetness(const soak_object *obj, soak_vec3 p, double u, double v)
{
    const soak_wetness *w = &obj->wetness;
    double x = 1.0;
    switch (w->type) {
    case SOAK_WETNESS_CONSTANT: x = w->value; break;
    case SOAK_WETNESS_MAP: {
        const soak_image *im = &w->map;
        double fu = u - floor(u), fv = v - floor(v);
        int px = (int)(fu * im->width), py = (int)((1.0 - fv) * im->height);
        px = px < 0 ? 0 : (px >= im->width ? im->width - 1 : px);
        py = py < 0 ? 0 : (py >= im->height ? im->height - 1 : py);
        const float *pix = im->pixels + ((size_t)py * im->width + px) * im->channels;
        int nc = im->channels >= 3 ? 3 : 1;
        double s = 0;
        for (int i = 0; i < nc; ++i) s += pix[i];
        x = s / nc;
        break;
    }
    case SOAK_WETNESS_PLANE: {
        double d = soak_v3_dot(w->normal, p) - w->offset;
        x = w->blend > 0 ? 0.5 - d / w->blend : (d < 0 ? 1.0 : 0.0);
        break;
    }
    }
    return x < 0 ? 0 : (x > 1 ? 1 : x);
}

const soak_model *soak_material_model(const soak_material *m, int wet)
{
    if (!m->model || wet || !m->model->exact) return m->model;
    return soak_model_find(m->model->exact);
}

void soak_material_model_params(const soak_material *m, int wet, soak_model_params out[3])
{
    int pores = m->model && strncmp(m->model->name, "porous", 6) == 0;
    for (int ch = 0; ch < 3; ++ch) {
        out[ch] = m->model_params[ch];
        if (!pores) out[ch].albedo = soak_rgb_at(m->wet_albedo, ch);
        if (wet) continue;
        out[ch].n_film = 1.0;
        out[ch].thickness = 0.0;
        out[ch].fill = 0.0;
    }
}
