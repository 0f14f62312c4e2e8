/* Model only what a scene needs (`soak advise`, `soak render --auto-model`):
 * per material of a scene, the cheapest model of soak_models() whose error
 * against the material's full description stays under a tolerance at the
 * angles and wetness the camera sees.
 *
 * What the camera sees: a grid of primary rays (pinhole at the camera) finds
 * the visible hits of each material, their viewing cosine and wetness. At
 * each hit the directional albedo of the full material and of every model
 * (soak/accuracy.h) is estimated; the predicted error of a model is the
 * relative RMS difference over the hits,
 *     e = sqrt(max(0, sum (R_m - R_f)^2 - noise) / sum R_f^2)
 * (sums over hits and channels; noise = the estimates' own variances), the
 * relative RMSE that material would make in an image under uniform light.
 * A model is chosen when e <= tol and one shading (eval + sample) costs less
 * than the full material's; otherwise the material is kept. Materials the
 * models cannot render (dielectrics, emitters, subsurface media) and
 * materials no primary ray hits are kept, with the reason. */
#ifndef SOAK_ADVISE_H
#define SOAK_ADVISE_H

#include <stddef.h>
#include <stdint.h>

#include "soak/models.h"
#include "soak/scene.h"
#include "soak/status.h"

#define SOAK_ADVISE_MAX_MODELS 32
#define SOAK_ADVISE_MAX_TOL 10 /* tol in (0, 10] */
#define SOAK_ADVISE_MAX_GRID 1024
#define SOAK_ADVISE_MIN_SAMPLES 16
#define SOAK_ADVISE_MAX_SAMPLES 1000000

typedef struct soak_advise_options {
    int grid_w, grid_h; /* primary rays, [1, SOAK_ADVISE_MAX_GRID] each (default 32 x 24) */
    int max_hits;       /* hits used per material, [1, 4096] (default 32) */
    int samples;        /* albedo samples per state and hit, [SOAK_ADVISE_MIN_SAMPLES, SOAK_ADVISE_MAX_SAMPLES] (default 256) */
    uint64_t seed;      /* default 1 */
    int cost_rounds;    /* rounds of 64 evaluations per cost measurement (default 50) */
} soak_advise_options;

void soak_advise_options_default(soak_advise_options *o);

typedef struct soak_advice {
    char material[64];
    int hits;                /* visible hits found (before max_hits) */
    double mean_wetness, mean_cos;
    const soak_model *model; /* NULL: keep the full material */
    double error;            /* predicted relative RMS error of the choice (0 when kept) */
    double full_ns, model_ns;/* one shading: eval + sample (ns); model_ns = full_ns when kept */
    char note[256];          /* why kept, or the runner-up */
    int n_tried;             /* every model that accepted the material */
    struct {
        const soak_model *model;
        double error, ns;
    } tried[SOAK_ADVISE_MAX_MODELS];
} soak_advice;

/* One entry per material of the scene (emitters included, kept), in the
 * scene's order; *advice is malloc'd (free()). tol in (0, SOAK_ADVISE_MAX_TOL]. */
soak_status soak_advise_scene(const soak_scene *scene, double tol, const soak_advise_options *opt, soak_advice **advice,
                              int *n, char *err, size_t errlen);

/* Switches every material with a chosen model to it (soak_scene_set_model). */
soak_status soak_advise_apply(soak_scene *scene, const soak_advice *advice, int n, char *err, size_t errlen);

#endif
