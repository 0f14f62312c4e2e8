/* Every model as a scene material, rendered: a large plane under a uniform
 * white sky (radiance 1, no lights) seen at one angle through a one-pixel
 * camera with a 0.2 degree field of view. The pixel must equal the model's
 * directional albedo at that angle (the plane sees only the sky), computed
 * here by a second method: quadrature of the model's own eval (soak/models.h,
 * not the BSDF layer the renderer samples through) plus its mirror lobe.
 * Tolerance: 4 standard errors of the repeated renders + 0.5 % (quadrature). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "soak/render.h"
#include "soak/scene.h"
#include "testutil.h"

#define STRETCH 0.15
#define QS 64
#define QP 48

/* Directional albedo of the non-delta part at wo, by quadrature over the half
 * vector, theta_h = atan(STRETCH tan s) (resolves narrow lobes), and the
 * delta part from the model's mirror reflectance. */
static double albedo_quadrature(const soak_model *m, const soak_model_ctx *ctx, soak_vec3 wo)
{
    static double xs[QS], ws[QS], xp[QP], wp[QP];
    tu_gauss_legendre(QS, 0, 0.5 * SOAK_PI, xs, ws);
    tu_gauss_legendre(QP, 0, 2 * SOAK_PI, xp, wp);
    double sum = 0;
    for (int a = 0; a < 4; ++a) /* four panels in s: the node density follows the lobes */
        for (int i = 0; i < QS; ++i) {
            double s = (a + xs[i] / (0.5 * SOAK_PI)) * 0.125 * SOAK_PI, ds = ws[i] / 4;
            double t = tan(s), th = atan(STRETCH * t), dth = STRETCH * (1 + t * t) / (1 + STRETCH * STRETCH * t * t);
            for (int j = 0; j < QP; ++j) {
                soak_vec3 h = soak_v3(sin(th) * cos(xp[j]), sin(th) * sin(xp[j]), cos(th));
                double oh = soak_v3_dot(wo, h), f = 0;
                if (!(oh > 0)) continue;
                soak_vec3 wi = soak_v3_norm(soak_v3_sub(soak_v3_scale(h, 2 * oh), wo));
                if (!(wi.z > 0) || soak_model_eval(m, ctx, wi, wo, &f) != SOAK_OK) continue;
                sum += ds * wp[j] * 4 * oh * sin(th) * dth * f * wi.z;
            }
        }
    double R = 0;
    if (m->mirror && m->mirror(ctx, wo.z, &R) != SOAK_OK) R = 0;
    return sum + R;
}

/* Renders the scene with material "m" (switched to `model` first when not
 * NULL) and compares its pixel with the model's directional albedo. */
/* Mean and standard error of the first pixel over 8 renders of 256 spp. */
static int render_mean(const soak_scene *scene, double *mean, double *se)
{
    double s1 = 0, s2 = 0;
    const int reps = 8;
    for (int r = 0; r < reps; ++r) {
        soak_render_options opt;
        soak_render_options_default(&opt);
        opt.threads = 2;
        opt.spp = 256;
        opt.seed = 11 + (uint64_t)r;
        soak_image img;
        soak_render_stats stats;
        char err[512];
        if (soak_render(scene, &opt, &img, &stats, err, sizeof err) != SOAK_OK) {
            printf("  render: %s\n", err);
            return 0;
        }
        double v = (img.pixels[0] + img.pixels[1] + img.pixels[2]) / 3.0;
        soak_image_free(&img);
        if (stats.nan_paths || stats.geometry_errors) return 0;
        s1 += v, s2 += v * v;
    }
    *mean = s1 / reps;
    *se = sqrt(fmax(0.0, s2 / reps - *mean * *mean) / (reps - 1));
    return 1;
}

static double render_case_model(const char *what, const char *material_json, double theta_deg, const char *model)
{
    double th = theta_deg * SOAK_PI / 180;
    char text[4096];
    snprintf(text, sizeof text,
             "{ \"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 8},"
             "  \"camera\": {\"position\": [0, %.9f, %.9f], \"look_at\": [0, 0, 0], \"fov\": 0.2},"
             "  \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
             "  \"materials\": {\"m\": %s},"
             "  \"objects\": [{\"type\": \"plane\", \"center\": [0, 0, 0], \"normal\": [0, 0, 1], \"size\": [10000, 10000],"
             " \"material\": \"m\"}] }",
             -5 * sin(th), 5 * cos(th), material_json);
    soak_scene scene;
    char err[1024] = "";
    if (!check_status(what, soak_scene_parse(text, what, ".", &scene, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return -1;
    }
    if (model && !check_status("soak_scene_set_model", soak_scene_set_model(&scene, "m", model, err, sizeof err), SOAK_OK))
        printf("  %s\n", err);
    const soak_material *m = &scene.materials[0];
    if (!check_true("material rendered through a model", m->type == SOAK_MAT_MODEL && m->model)) {
        soak_scene_free(&scene);
        return -1;
    }
    soak_model_params q[3];
    soak_material_model_params(m, 1, q);
    soak_vec3 wo = soak_v3(sin(th), 0, cos(th));
    double ref = 0;
    for (int ch = 0; ch < 3; ++ch) {
        soak_model_ctx ctx;
        if (!check_status("model set-up", m->model->setup(&q[ch], &ctx), SOAK_OK)) break;
        ref += albedo_quadrature(m->model, &ctx, wo) / 3;
    }
    double mean = 0, se = 0;
    int ok = render_mean(&scene, &mean, &se);
    soak_scene_free(&scene);
    if (!check_true("rendered", ok)) return -1;
    char msg[256];
    double bound = 4 * se + 5e-3 * ref;
    snprintf(msg, sizeof msg, "%s at %.0f deg: rendered %.5f +- %.5f = directional albedo %.5f (|d| %.2g <= %.2g)", what,
             theta_deg, mean, se, ref, fabs(mean - ref), bound);
    printf("  %s\n", msg);
    check_true(msg, fabs(mean - ref) <= bound);
    return ref;
}

static void render_case(const char *what, const char *material_json, double theta_deg)
{
    (void)render_case_model(what, material_json, theta_deg, NULL);
}

/* soak_scene_set_model: the hook for rendering one scene with another model. */
static void test_set_model(void)
{
    const char *wet = "{\"type\": \"wet\", \"film\": {\"ior\": 1.333}, \"base\": {\"type\": \"lambert\", \"albedo\": 0.6}}";
    /* The film model of the table is the closed form the native wet material
     * renders with: the same number both ways (the native one is checked
     * against the same quadrature reference below). */
    double ref = render_case_model("wet lambert switched to the film model", wet, 50, "film");
    soak_scene scene;
    char err[512] = "", text[2048];
    double th = 50 * SOAK_PI / 180, mean = 0, se = 0;
    snprintf(text, sizeof text,
             "{ \"render\": {\"width\": 1, \"height\": 1, \"max_depth\": 8},"
             "  \"camera\": {\"position\": [0, %.9f, %.9f], \"look_at\": [0, 0, 0], \"fov\": 0.2},"
             "  \"environment\": {\"type\": \"constant\", \"radiance\": 1}, \"materials\": {\"m\": %s},"
             "  \"objects\": [{\"type\": \"plane\", \"normal\": [0, 0, 1], \"size\": [10000, 10000], \"material\": \"m\"}] }",
             -5 * sin(th), 5 * cos(th), wet);
    if (check_status("native wet scene", soak_scene_parse(text, "native", ".", &scene, err, sizeof err), SOAK_OK)) {
        if (check_true("native wet rendered", render_mean(&scene, &mean, &se))) {
            char msg[200];
            snprintf(msg, sizeof msg, "native wet lambert (closed-form film): %.5f +- %.5f = film model albedo %.5f", mean, se, ref);
            printf("  %s\n", msg);
            check_true(msg, fabs(mean - ref) <= 4 * se + 5e-3 * ref);
        }
        soak_scene_free(&scene);
    }
    render_case_model("wet lambert switched to ww", wet, 50, "ww");
    render_case_model("wet lambert switched to porous-ggx", wet, 50, "porous-ggx");
    const char *lambert = "{\"type\": \"lambert\", \"albedo\": 0.35}";
    render_case_model("lambert switched to the lambert model", lambert, 60, "lambert");
    const char *glass = "{\"camera\": {\"position\": [0, -5, 1], \"look_at\": [0, 0, 0]}, \"environment\": {\"type\": \"constant\", \"radiance\": 1},"
                       " \"materials\": {\"g\": {\"type\": \"dielectric\"}, \"l\": {\"type\": \"lambert\", \"albedo\": 0.5}},"
                       " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"g\"},"
                       " {\"type\": \"sphere\", \"center\": [3, 0, 0], \"radius\": 1, \"material\": \"l\"}]}";
    if (!check_status("set_model scene", soak_scene_parse(glass, "set_model", ".", &scene, err, sizeof err), SOAK_OK)) {
        printf("  %s\n", err);
        return;
    }
    check_status("glass has no model view", soak_scene_set_model(&scene, "g", "ww", err, sizeof err), SOAK_ERR_UNSUPPORTED);
    printf("  %s\n", err);
    check_status("unknown model", soak_scene_set_model(&scene, "l", "nope", err, sizeof err), SOAK_ERR_NOT_FOUND);
    printf("  %s\n", err);
    check_status("unknown material", soak_scene_set_model(&scene, "x", "ww", err, sizeof err), SOAK_ERR_NOT_FOUND);
    check_true("a failed switch leaves the material as it was", scene.materials[1].type == SOAK_MAT_LAMBERT);
    soak_scene_free(&scene);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    const char *ww = "{\"type\": \"ww\", \"albedo\": 0.7, \"roughness\": 0.3, \"film\": {\"ior\": 1.333}}";
    const char *triace = "{\"type\": \"ww-triace\", \"albedo\": 0.7, \"roughness\": 0.3, \"film\": {\"ior\": 1.333}}";
    const char *porous = "{\"type\": \"porous\", \"albedo\": 0.6, \"roughness\": 0.4, \"fill\": 0.5}";
    const char *porous_ggx = "{\"type\": \"porous-ggx\", \"albedo\": 0.6, \"roughness\": 0.4, \"fill\": 0.5}";
    const char *copper = "{\"type\": \"ww\", \"ior\": [0.27, 0.68, 1.3], \"k\": [3.6, 2.6, 2.3], \"roughness\": 0.25,"
                         " \"film\": {\"ior\": 1.333, \"thickness\": 0.5, \"absorption\": [0.4, 0.1, 0]}}";
    const char *sand = "{\"type\": \"preset\", \"name\": \"sand\", \"wetness\": 0.6, \"model\": \"porous-ggx\"}";
    const char *brick = "{\"type\": \"preset\", \"name\": \"brick\", \"wetness\": 1, \"model\": \"ww\"}";
    for (int a = 0; a < 2; ++a) {
        double theta = a == 0 ? 30 : 70;
        render_case("ww", ww, theta);
        render_case("ww-triace", triace, theta);
        render_case("porous", porous, theta);
        render_case("porous-ggx", porous_ggx, theta);
    }
    render_case("ww over copper, absorbing film", copper, 50);
    render_case("preset sand through porous-ggx", sand, 50);
    render_case("preset brick through ww", brick, 50);
    test_set_model();
    return check_finish();
}
