/* The scene's materials made BSDFs, once per render (render_bsdfs.c). */
#ifndef SOAK_RENDER_BSDFS_H
#define SOAK_RENDER_BSDFS_H

#include "rt_ctx.h"

/* Sets up bsdfs[i] for every material (n_materials entries); trace_films:
 * films over Lambert traced bounce by bounce instead of their closed form.
 * On failure err names the material. */
soak_status rt_bsdfs_setup(const soak_scene *s, int trace_films, rt_material_bsdf *bsdfs, char *err, size_t errlen);
/* The same for one material. */
soak_status rt_material_bsdf_setup(const soak_material *m, int trace_films, rt_material_bsdf *out);

#endif
