/* Instructions per BSDF evaluation, for scripts/accuracy_report.sh: runs n
 * evaluations (soak_bsdf_eval, RGB value and pdf, 64 fixed direction pairs)
 * of one model at soak_model_params_default (the wet state: water film, pores
 * full), or "full": the tracer's closed-form water film over a Lambert base.
 * Linked only against libsoak_models and libsoak_core (no OpenImageIO: its
 * libhwy start-up code uses an instruction valgrind 3.19 cannot run).
 *   accuracy_callgrind MODEL N */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/bsdf.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: accuracy_callgrind MODEL|full N\n");
        return 2;
    }
    long n = atol(argv[2]);
    soak_bsdf_desc d;
    if (strcmp(argv[1], "full") == 0) {
        soak_bsdf_desc_default(&d, SOAK_BSDF_LAMBERT);
        d.film_ior = 1.333;
        d.film_thickness = 1e-3;
    } else {
        soak_bsdf_desc_default(&d, SOAK_BSDF_MODEL);
        d.model = soak_model_find(argv[1]);
        if (!d.model) {
            fprintf(stderr, "accuracy_callgrind: MODEL: no model named '%s'\n", argv[1]);
            return 2;
        }
    }
    soak_bsdf b;
    if (soak_bsdf_setup(&d, &b) != SOAK_OK || (soak_bsdf_get_flags(&b) & SOAK_BSDF_WALK)) {
        fprintf(stderr, "accuracy_callgrind: %s: set-up failed or no closed-form eval\n", argv[1]);
        return 1;
    }
    double sum = 0;
    if (soak_bsdf_eval_loop(&b, n, &sum) != SOAK_OK) return 1;
    printf("%s %ld checksum %.6g\n", argv[1], n, sum);
    return 0;
}
