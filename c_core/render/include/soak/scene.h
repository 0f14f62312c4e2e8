/* JSON scene description for the reference path tracer (`soak render`).
 * The format is documented with a complete example in scenes/README.md.
 *
 * Every error message has the form "<file>: <json path>: <reason>", e.g.
 * "scene.json: objects[2].radius: must be > 0, got -1", or for syntax
 * errors "scene.json: line 12, column 5: JSON syntax error". Unknown keys
 * are errors (a misspelt key would otherwise be silently ignored). Relative
 * file names inside a scene (meshes, wet maps, environment maps, volumes)
 * are resolved against the scene file's folder.
 *
 * Units: a scene has its own length unit (positions, sizes, film
 * thicknesses; coefficients per that unit), not necessarily metres. A
 * preset material's chain is in SI (m, 1/m, soak/wetness.h); its "unit_mm"
 * (the scene unit in mm, default 1000) converts it to the scene's unit once,
 * where the material is parsed (soak/units.h); the tracer sees only scene
 * units. */
#ifndef SOAK_SCENE_H
#define SOAK_SCENE_H

#include <stddef.h>

#include "soak/volume.h"
#include "soak/geometry.h"
#include "soak/hg.h"
#include "soak/image.h"
#include "soak/models.h"
#include "soak/status.h"
#include "soak/vec.h"

typedef struct soak_camera {
    soak_vec3 position, look_at, up;
    double fov_deg;        /* vertical field of view, (0, 179] */
    double aperture;       /* lens radius, 0 = pinhole */
    double focus_distance; /* > 0; default |look_at - position| */
    double exposure;       /* stops, applied before the PNG tone curve */
} soak_camera;

typedef enum soak_light_type {
    SOAK_LIGHT_DIRECTIONAL = 0, /* sun: delta direction */
    SOAK_LIGHT_POINT,
    SOAK_LIGHT_SPHERE /* spherical area light, also a geometry object */
} soak_light_type;

typedef struct soak_light {
    soak_light_type type;
    soak_vec3 direction; /* unit, pointing TO the light (directional) */
    soak_vec3 position;  /* point / sphere centre */
    double radius;       /* sphere */
    soak_rgb value;      /* irradiance (directional, W/m^2 on a surface facing it),
                            intensity (point, W/sr), radiance (sphere) */
    unsigned object_id;  /* sphere: its geometry object */
} soak_light;

typedef enum soak_env_type { SOAK_ENV_NONE = 0, SOAK_ENV_CONSTANT, SOAK_ENV_MAP } soak_env_type;

typedef struct soak_environment {
    soak_env_type type;
    soak_rgb radiance;   /* constant */
    soak_image map;      /* equirectangular, +z up, top row = zenith */
    double scale;        /* multiplies the map */
    double rotation_deg; /* about +z */
} soak_environment;

/* Participating medium of a wet material's scattering base. Coefficients
 * per scene length unit. With a volume, the parameters inside the volume's
 * box (placed at volume_origin) come from the grid (trilinear); outside it
 * the homogeneous values below apply. */
typedef struct soak_scene_medium {
    soak_rgb sigma_s, sigma_a;
    soak_hg2 phase;
    double ior;                /* material index n3, [1, 3] */
    soak_volume *volume;       /* owned by the scene; NULL = homogeneous */
    soak_vec3 volume_origin;
    double majorant;           /* max sigma_t over channels and the volume */
} soak_scene_medium;

typedef enum soak_material_type {
    SOAK_MAT_LAMBERT = 0,
    SOAK_MAT_DIELECTRIC,
    SOAK_MAT_CONDUCTOR,
    SOAK_MAT_WET,
    SOAK_MAT_EMITTER, /* sphere lights */
    SOAK_MAT_MODEL    /* an entry of soak_models() (ww, ww-triace, porous, porous-ggx, ...) */
} soak_material_type;

typedef enum soak_base_type { SOAK_BASE_LAMBERT = 0, SOAK_BASE_GGX, SOAK_BASE_MEDIUM } soak_base_type;

typedef struct soak_material {
    char name[64];
    soak_material_type type;
    /* lambert, and the lambert base of wet */
    soak_rgb albedo;
    /* dielectric: index and interior absorption (1/length) */
    double ior;
    soak_rgb absorption;
    /* conductor, and the ggx base of wet: complex index relative to vacuum/air, GGX alpha */
    soak_rgb eta, k;
    double alpha;
    /* wet: film ([JLD99] Eq. 1-4) and base */
    double film_ior;       /* n2, [1, 3] */
    double film_k;         /* Fresnel exponent k of the film-material interface */
    double film_thickness; /* scene length unit, for absorption */
    soak_rgb film_absorption; /* per scene length unit */
    double film_coverage;  /* probability of the film at a wet point, [0,1] (1 unless a preset says less) */
    double film_pore_share; /* of those draws, the share that is pore water: the liquid interface at zero
                             * thickness over the base without its coat (wetness.h step 5,
                             * wet_specular.h point 4); from a preset's chain, or the film's
                             * "pore_share" (default 0). Surface and medium bases, and soak advise's
                             * estimates (accuracy.h) */
    soak_base_type base;
    /* a preset's lambert base: the material's own rough interface over it
     * (soak/bsdf.h COATED: GGX of width alpha, index ior relative to air,
     * specular weight coat_weight = 1 - porosity, wetness.h step 6); under
     * the liquid its index is relative to the liquid. 0: no interface. */
    double coat_weight;
    /* the same interface's weight in the dry draw, which holds every grain
     * outside the film: ks / (1 - porosity fill) (soak/wet_specular.h point 4,
     * soak_wet_grain_coat_weight), so that the lobe in air weighs ks (1 - c);
     * the pore-water draw has no coat (its body under the flat liquid). Where
     * an object's wetness (map, plane) is below 1 the dry draw also stands for
     * its drier points, as its albedo (the chain's at the material's wetness)
     * does: there the lobe is k_dry, not the dry chain's ks. */
    double dry_coat_weight;
    soak_scene_medium medium;     /* wet state (and dry when has_dry == 0) */
    soak_scene_medium dry_medium; /* base medium where the object is dry */
    int has_dry;
    soak_rgb radiance; /* emitter */
    /* model: the wet state (per channel); the dry state is the same with
     * n_film 1, thickness 0 and fill 0. Every lambert, conductor, wet
     * (lambert or ggx base) and preset material also fills model_params with
     * its own description, so that soak_scene_set_model can render it
     * through any model. */
    const soak_model *model;
    soak_model_params model_params[3];
    soak_rgb wet_albedo; /* albedo for models that do not model pores */
    int has_model_params;
    /* An opaque or metal preset's states at other liquid amounts, for
     * objects whose wetness (a map, a plane, a constant below 1) scales the
     * material's: the chain at the point's liquid amount (scene_levels.h).
     * NULL for every other material. Owned by the scene. */
    struct soak_material_levels *levels;
} soak_material;

typedef enum soak_wetness_type {
    SOAK_WETNESS_CONSTANT = 0,
    SOAK_WETNESS_MAP,   /* image over UV, mean of colour channels, clamped to [0,1] */
    SOAK_WETNESS_PLANE  /* wet where dot(normal, p) < offset, linear blend of width blend */
} soak_wetness_type;

typedef struct soak_wetness {
    soak_wetness_type type;
    double value;       /* constant */
    soak_image map;     /* map: u right, v up (v = 0 is the bottom row) */
    soak_vec3 normal;   /* plane */
    double offset, blend;
} soak_wetness;

typedef struct soak_object {
    soak_shape_kind shape;
    unsigned object_id; /* geometry object */
    int material;       /* index into materials */
    soak_wetness wetness;
} soak_object;

/* Default of render.walk_guide (see soak_scene.walk_guide). */
#define SOAK_RENDER_WALK_GUIDE 0.0
/* Limits of a scene's "render" block (scene.c) and of the same
 * soak_render_options (soak/render.h). */
#define SOAK_RENDER_MAX_SIZE 16384   /* width, height */
#define SOAK_RENDER_MAX_SPP 10000000 /* samples per pixel */
#define SOAK_RENDER_MAX_DEPTH 100000 /* path length */

typedef struct soak_scene {
    char path[1024];
    int width, height, spp, max_depth;
    long long caustic_photons; /* volume photon map for caustics into media; 0 = off */
    double caustic_radius;     /* photon gather radius (scene length unit) */
    /* Probability of the Dwivedi guide at each scattering of a homogeneous
     * medium's walk toward the face the path entered through
     * (soak_walk_options.guide_prob; render.walk_guide, [0, 0.99], 0 = the
     * analog walk). */
    double walk_guide;
    soak_camera camera;
    soak_environment env;
    soak_light *lights;
    int n_lights;
    soak_material *materials;
    int n_materials;
    soak_object *objects; /* indexed by geometry object id */
    int n_objects;
    soak_geometry *geometry;
    char **inputs; /* every file the scene reads (for -o checks) */
    int n_inputs;
} soak_scene;

/* Reads and validates a scene file; builds and commits its geometry. */
soak_status soak_scene_load(const char *path, soak_scene *scene, char *err, size_t errlen);
/* Same from text; name is used in messages, base_dir resolves relative files. */
soak_status soak_scene_parse(const char *text, const char *name, const char *base_dir, soak_scene *scene, char *err,
                             size_t errlen);
void soak_scene_free(soak_scene *scene);

/* Renders material `material` (by name) through the model `model` (a name
 * of soak_models()) from its own description (model_params): the hook for
 * comparing models on one scene. Fails (message in err) for an unknown
 * material or model, a material without a model view (dielectric, emitter,
 * medium base) or parameters the model rejects. */
soak_status soak_scene_set_model(soak_scene *scene, const char *material, const char *model, char *err, size_t errlen);

/* The parameters a model material is rendered with, per channel: the wet
 * state, or (wet = 0) the dry one (no film, no pore water). The porous
 * models take the dry albedo (they darken it themselves), the others
 * wet_albedo. */
void soak_material_model_params(const soak_material *m, int wet, soak_model_params out[3]);
/* The model of the wet state (m->model) or of the dry one: a fast path's
 * exact peer (without liquid a fast path approximates nothing, and Tri-Ace
 * accepts water-like film indices only). */
const soak_model *soak_material_model(const soak_material *m, int wet);

/* Wetness in [0,1] of object at a hit (position and uv). */
double soak_scene_wetness(const soak_object *obj, soak_vec3 p, double u, double v);

#endif
