#include "soak/preset_json.h"

void soak_json_preset_optics(soak_json *j, cJSON *o, const soak_preset *p, const char *albedo_key,
                             int with_sources)
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
