/* soak_model_eval's fast path (soak/models.h, eval_fast): for every model
 * that has one, the value equals the model's own checked eval (a second
 * code path) within 1e-12 relative on 2000 random direction pairs; a context
 * that no set-up of this model filled (zeroed, or set up by another model)
 * and NaN / non-unit directions are refused with SOAK_ERR_ARG. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "soak/models.h"
#include "soak/rng.h"

static soak_vec3 random_dir(soak_rng *r)
{
    double z = 0.01 + 0.99 * soak_rng_uniform(r), phi = 2 * SOAK_PI * soak_rng_uniform(r), s = sqrt(1 - z * z);
    return soak_v3(s * cos(phi), s * sin(phi), z);
}

int main(void)
{
    size_t n;
    const soak_model *models = soak_models(&n);
    soak_model_params p;
    soak_model_params_default(&p);
    static soak_model_ctx ctx, zero, other;
    int fast = 0;
    for (size_t m = 0; m < n; ++m) {
        if (!models[m].eval_fast) continue;
        ++fast;
        char what[160];
        snprintf(what, sizeof what, "%s: set-up", models[m].name);
        check_status(what, models[m].setup(&p, &ctx), SOAK_OK);
        soak_rng r;
        soak_rng_seed(&r, 24, m);
        double worst = 0.0;
        int bad = 0;
        for (int k = 0; k < 2000; ++k) {
            soak_vec3 wi = random_dir(&r), wo = random_dir(&r);
            double a = -1, b = -1;
            bad += soak_model_eval(&models[m], &ctx, wi, wo, &a) != SOAK_OK;
            bad += models[m].eval(&ctx, wi, wo, &b) != SOAK_OK;
            if (b > 0) worst = fmax(worst, fabs(a - b) / b);
        }
        snprintf(what, sizeof what, "%s: fast path vs checked eval, max rel diff", models[m].name);
        check_close(what, worst, 0.0, 1e-12);
        snprintf(what, sizeof what, "%s: every call succeeded", models[m].name);
        check_true(what, bad == 0);
        double f = 0;
        soak_vec3 z = soak_v3(0, 0, 1);
        memset(&zero, 0, sizeof zero);
        snprintf(what, sizeof what, "%s: zeroed context refused", models[m].name);
        check_status(what, soak_model_eval(&models[m], &zero, z, z, &f), SOAK_ERR_ARG);
        const soak_model *lam = soak_model_find("lambert");
        lam->setup(&p, &other);
        snprintf(what, sizeof what, "%s: lambert's context refused", models[m].name);
        check_status(what, soak_model_eval(&models[m], &other, z, z, &f), SOAK_ERR_ARG);
        snprintf(what, sizeof what, "%s: NaN direction refused", models[m].name);
        check_status(what, soak_model_eval(&models[m], &ctx, soak_v3(NAN, 0, 1), z, &f), SOAK_ERR_ARG);
        snprintf(what, sizeof what, "%s: non-unit direction refused", models[m].name);
        check_status(what, soak_model_eval(&models[m], &ctx, z, soak_v3(0, 0, 1.001), &f), SOAK_ERR_ARG);
    }
    check_true("film-ctx and ww-triace have fast paths", fast >= 2);
    return check_finish();
}
