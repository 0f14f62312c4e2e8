/* Nusselt's falling film on the faces of a rain-baked mesh (model in
 * soak/bake_rain.h, step 3b). */
#include "bake_rain_film.h"

#include <math.h>
#include <stdlib.h>

#include "soak/bake_rain.h"

double soak_rain_film_thickness(double q, double sin_theta)
{
    if (!(q > 0.0 && q < 1e300) || !(sin_theta > 0.0)) return 0.0;
    double s = sin_theta < 1.0 ? sin_theta : 1.0;
    double h = cbrt(3.0 * SOAK_RAIN_WATER_VISCOSITY * q / (SOAK_RAIN_WATER_DENSITY * SOAK_RAIN_GRAVITY * s));
    return h < SOAK_RAIN_FILM_MAX ? h : SOAK_RAIN_FILM_MAX;
}

double soak_rain_film_surface_speed(double h, double sin_theta)
{
    if (!(h > 0.0 && h <= SOAK_RAIN_FILM_MAX) || !(sin_theta > 0.0)) return 0.0;
    double s = sin_theta < 1.0 ? sin_theta : 1.0;
    return SOAK_RAIN_WATER_DENSITY * SOAK_RAIN_GRAVITY * s * h * h / (2.0 * SOAK_RAIN_WATER_VISCOSITY);
}

soak_status soak_rain_film_map(const soak_rain_flow_grid *g, const float *up_dot_n, const float *exposure,
                               double rain_m_s, double evap_m_s, double *film, soak_rain_flow_balance *balance)
{
    if (!g || !up_dot_n || !exposure || !film) return SOAK_ERR_NULL;
    if (!(rain_m_s >= 0.0 && rain_m_s < 1.0) || !(evap_m_s >= 0.0 && evap_m_s < 1.0)) return SOAK_ERR_ARG;
    size_t n = (size_t)g->w * g->h;
    double *source = calloc(n, sizeof *source), *discharge = calloc(n, sizeof *discharge);
    soak_rain_flow_balance local;
    soak_status st = source && discharge ? SOAK_OK : SOAK_ERR_NOMEM;
    for (size_t i = 0; i < n && st == SOAK_OK; ++i)
        source[i] = g->covered[i] && exposure[i] > 0.0f ? rain_m_s * exposure[i] * g->area[i] : 0.0;
    if (st == SOAK_OK) st = soak_rain_flow_discharge(g, source, evap_m_s, discharge, balance ? balance : &local);
    for (size_t i = 0; i < n && st == SOAK_OK; ++i) {
        film[i] = 0.0;
        if (!g->covered[i] || !(g->area[i] > 0.0f)) continue;
        double c = up_dot_n[i], s2 = 1.0 - c * c;
        film[i] = soak_rain_film_thickness(discharge[i] / soak_rain_flow_width(g, i), sqrt(s2 > 0.0 ? s2 : 0.0));
    }
    free(source);
    free(discharge);
    return st;
}
