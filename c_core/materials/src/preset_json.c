#include "soak/preset_json.h"

#include "soak/film.h"
#include "soak/fresnel.h"
#include "soak/units.h"

void soak_json_preset_optics(soak_json *j, cJSON *o, const soak_preset *p, const char *albedo_key, int with_sources)
{
    soak_json_str(j, o, "name", p->name);
    soak_json_str(j, o, "display_name", p->display_name);
    soak_json_str(j, o, "kind", soak_material_kind_name(p->kind));
    soak_json_rgb(j, o, albedo_key, p->albedo);
    if (with_sources) soak_json_str(j, o, "albedo_source", p->albedo_source);
    soak_json_num(j, o, "ggx_alpha_dry", p->ggx_alpha_dry);
    soak_json_num(j, o, "ggx_alpha_wet", p->ggx_alpha_wet);
    if (with_sources) soak_json_str(j, o, "roughness_source", p->roughness_source);
    if (p->kind == SOAK_KIND_CONDUCTOR) {
        soak_json_rgb(j, o, "ior_n", p->ior_n);
        soak_json_rgb(j, o, "ior_k", p->ior_k);
    } else {
        soak_json_num(j, o, "ior", p->ior);
    }
    if (with_sources) soak_json_str(j, o, "ior_source", p->ior_source);
    soak_json_num(j, o, "porosity", p->porosity);
    soak_json_num(j, o, "saturation_wetness", soak_material_kind_porous(p->kind) ? p->porosity : 0.0);
}

soak_status soak_json_liquid(soak_json *j, cJSON *list, const soak_liquid *l, soak_json_length unit, int with_film)
{
    cJSON *o = soak_json_object(j, list, NULL);
    if (!o) return SOAK_ERR_NOMEM;
    int mm = unit == SOAK_JSON_PER_MM;
    soak_json_str(j, o, "name", l->name);
    soak_json_str(j, o, "display_name", l->display_name);
    soak_json_num(j, o, "ior", l->ior);
    soak_json_rgb(j, o, mm ? "sigma_a_per_mm" : "sigma_a_per_m",
                  mm ? soak_rgb_per_mm_from_per_m(l->sigma_a_per_m) : l->sigma_a_per_m);
    soak_json_rgb(j, o, mm ? "sigma_s_per_mm" : "sigma_s_per_m",
                  mm ? soak_rgb_per_mm_from_per_m(l->sigma_s_per_m) : l->sigma_s_per_m);
    if (with_film) {
        double f0 = 0.0, hemi = 0.0;
        soak_status st = soak_fresnel_r0(l->ior, 0.0, &f0);
        soak_film film = {l->ior, 0.0, 0.0};
        if (st == SOAK_OK) st = soak_film_albedo_diffuse(&film, 0.0, &hemi);
        if (st != SOAK_OK) return st;
        soak_json_num(j, o, "film_normal_reflectance", f0);
        soak_json_num(j, o, "film_hemispherical_reflectance", hemi);
    }
    soak_json_str(j, o, "source", l->source);
    return j->ok ? SOAK_OK : SOAK_ERR_NOMEM;
}
