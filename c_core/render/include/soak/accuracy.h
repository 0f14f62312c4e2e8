/* Speed against error: how far a model of soak_models() rendering a scene
 * material is from the material's full description, and what it costs.
 * Shared by `soak report` (a fixed grid of presets) and `soak advise` /
 * `soak render --auto-model` (the materials of one scene).
 *
 * The measure is the directional albedo R(cos_o) (RGB) of a material as the
 * renderer shades it (the BSDFs render.c sets up, soak/bsdf.h): the wet BSDF
 * with probability wetness * film_coverage, else the dry one, each estimated
 * by Monte Carlo with the renderer's own sampling (soak_bsdf_sample_dir).
 * Under uniform lighting R times the
 * irradiance is the radiance a camera sees, so a relative error in R is the
 * relative error in radiance that material makes in such an image.
 * Reproducible: the estimate depends only on the arguments and the seed. */
#ifndef SOAK_ACCURACY_H
#define SOAK_ACCURACY_H

#include <stddef.h>
#include <stdint.h>

#include "soak/scene.h"
#include "soak/status.h"
#include "soak/vec.h"

typedef struct soak_albedo_estimate {
    soak_rgb value;     /* directional albedo, including delta lobes */
    soak_rgb std_error; /* Monte Carlo standard error per channel */
} soak_albedo_estimate;

/* 1 when the renderer shades m at a surface through BSDFs (lambert,
 * conductor, wet over lambert/ggx, model materials): the ones this file can
 * measure. 0 for dielectrics, emitters and media bases (subsurface walks). */
int soak_accuracy_supported(const soak_material *m);

/* R(cos_o) of m at object wetness w in [0, 1], cos_o in (0, 1], samples in
 * [1, 1e8] per state; trace_films as soak_render_options. SOAK_ERR_UNSUPPORTED
 * for materials of soak_accuracy_supported() == 0. */
soak_status soak_material_albedo(const soak_material *m, double wetness, double cos_o, int samples, uint64_t seed,
                                 int trace_films, soak_albedo_estimate *out);

/* Light arriving at a shading point, in its local frame (normal +z). */
typedef struct soak_local_light {
    soak_vec3 wi;     /* unit, toward the light, wi.z > 0 */
    soak_rgb irradiance; /* on a surface facing the light (W/m^2) */
} soak_local_light;

/* Radiance toward wo (local frame, wo.z > 0) of m at object wetness w under
 * uniform environment radiance env plus the given lights (no shadows here:
 * the caller leaves occluded lights out):
 *     L = R(wo) env + sum_l f(wi_l, wo) cos(wi_l) E_l,
 * R by Monte Carlo as soak_material_albedo (delta lobes reflect env), f by
 * soak_bsdf_eval with the same dry/wet mixture (a traced film's f: the mean
 * of samples estimates, soak_bsdf_eval_mean). The one-bounce radiance under the scene's own lights, for soak/advise.h. */
soak_status soak_material_radiance(const soak_material *m, double wetness, soak_vec3 wo, soak_rgb env,
                                   const soak_local_light *lights, int n_lights, int samples, uint64_t seed,
                                   soak_albedo_estimate *out);

/* The same for many shading points of one material: the BSDFs (and the
 * tables some models build at set-up) are made once. The material must
 * outlive the handle. */
typedef struct soak_shading_material soak_shading_material;
soak_status soak_shading_material_new(const soak_material *m, soak_shading_material **out);
soak_status soak_shading_radiance(const soak_shading_material *p, double wetness, soak_vec3 wo, soak_rgb env,
                                  const soak_local_light *lights, int n_lights, int samples, uint64_t seed,
                                  soak_albedo_estimate *out);
void soak_shading_material_free(soak_shading_material *p);

/* Cost of shading m once, as the renderer does per hit of the wet state
 * (dry when the material has none): eval_ns is soak_bsdf_eval_cost_ns
 * (RGB value and pdf, wall-clock CPU time, n_rounds rounds of 64 pairs);
 * sample_ns one soak_bsdf_sample_dir (for a traced film: one walk through
 * it, and eval one estimate of f and of pdf). For reports, never
 * for tests. */
soak_status soak_material_cost(const soak_material *m, int n_rounds, double *eval_ns, double *sample_ns);

/* Runs n evaluations of m's wet BSDF over the same 64 direction pairs as
 * soak_material_cost, with no timing: `soak report --cost-only` runs it
 * under valgrind --tool=callgrind to count instructions per evaluation.
 * Returns a checksum so the work is not optimised away. */
soak_status soak_material_eval_loop(const soak_material *m, long n, double *checksum);

/* A one-material scene (material "m" of preset `preset` at preset wetness
 * `wetness` with `liquid`, an object of wetness 1) parsed as `soak render`
 * would; free with soak_scene_free. */
soak_status soak_accuracy_preset_scene(const char *preset, const char *liquid, double wetness, soak_scene *scene,
                                       char *err, size_t errlen);

#endif
