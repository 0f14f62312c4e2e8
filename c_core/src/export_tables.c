/* Knots and base-colour tables of soak export (soak/export.h): placeholder,
 * being written. */
#include "soak/export.h"

soak_status soak_export_knots(const soak_preset *preset, const soak_liquid *liquid, double film_thickness_m,
                              double *knots, int max, int *n)
{
    (void)preset;
    (void)liquid;
    (void)film_thickness_m;
    (void)knots;
    (void)max;
    (void)n;
    return SOAK_ERR_UNSUPPORTED;
}

soak_status soak_wet_params_for_base(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_input *in,
                                     soak_rgb dry, soak_wet_params *out)
{
    (void)preset;
    (void)liquid;
    (void)in;
    (void)dry;
    (void)out;
    return SOAK_ERR_UNSUPPORTED;
}

soak_status soak_export_base_nodes(const soak_preset *preset, const soak_liquid *liquid, double *albedo_nodes,
                                   int max_albedo, int *n_albedo, double *wet_knots, int max_wet, int *n_wet)
{
    (void)preset;
    (void)liquid;
    (void)albedo_nodes;
    (void)max_albedo;
    (void)n_albedo;
    (void)wet_knots;
    (void)max_wet;
    (void)n_wet;
    return SOAK_ERR_UNSUPPORTED;
}
