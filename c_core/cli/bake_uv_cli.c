/* See bake_uv_cli.h. */
#include "bake_uv_cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int read_uv_set(const char *cmd, const cli_opt *o, const char *text, void *dst)
{
    bake_uv_opts *u = dst;
    char *end = NULL;
    long k = strtol(text, &end, 10);
    memset(&u->uv, 0, sizeof u->uv);
    if (end != text && *end == '\0') {
        if (k < 0 || k >= SOAK_MESH_UV_SETS) {
            cli_error(cmd, "%s: UV set index %ld is outside 0..%d", o->name, k, SOAK_MESH_UV_SETS - 1);
            return 0;
        }
        u->uv.uv_index = (int)k;
        return 1;
    }
    if (!text[0] || strlen(text) >= sizeof u->uv.uv_name) {
        cli_error(cmd, "%s: a UV set name of 1..%zu bytes, or an index 0..%d", o->name, sizeof u->uv.uv_name - 1,
                  SOAK_MESH_UV_SETS - 1);
        return 0;
    }
    snprintf(u->uv.uv_name, sizeof u->uv.uv_name, "%s", text);
    return 1;
}

static const cli_choice outside_modes[] = {
    {"wrap", SOAK_UV_WRAP, 0}, {"skip", SOAK_UV_SKIP, 0}, {"refuse", SOAK_UV_REFUSE, 0}, {NULL, 0, 0}};

#define F(field) CLI_FIELD(bake_uv_opts, field)
const cli_opt bake_uv_opts_table[] = {
    {"--uv-set", NULL, CLI_OPT_CUSTOM, .parse = read_uv_set, .meta = "N|NAME",
     .help = "the mesh's UV set: its index (default 0) or its name (FBX, Collada)"},
    {"--uv-outside", NULL, CLI_OPT_CHOICE, .choices = outside_modes, F(outside), .meta = "wrap|skip|refuse",
     .help = "faces with UVs outside [0,1]: wrap as a repeating texture (default),\n"
             "leave out (counted), or refuse the bake. -o with <UDIM> bakes one\n"
             "map per UDIM tile instead (1001 + u + 10 v)"},
    {"--strict", NULL, CLI_OPT_FLAG, .flag = 1, F(strict),
     .help = "fail (exit 1, nothing written) where the bake would warn: an empty map,\n"
             "faces without UVs, faces holding over half the UV area between texels,\n"
             "or covered texels none of which sees the sky"},
};
#undef F
const size_t bake_uv_opts_table_n = sizeof bake_uv_opts_table / sizeof bake_uv_opts_table[0];

void bake_uv_opts_init(bake_uv_opts *u)
{
    memset(u, 0, sizeof *u);
    u->outside = SOAK_UV_WRAP;
}

int bake_uv_verdict(const char *cmd, const char *mesh, const soak_uv_stats *s, const bake_uv_opts *u)
{
    char msg[1024];
    if (!soak_uv_stats_warning(s, msg, sizeof msg)) return 0;
    if (u->strict) {
        cli_error(cmd, "%s: %s; --strict: nothing written", mesh, msg);
        return 1;
    }
    fprintf(stderr, "soak %s: warning: %s: %s\n", cmd, mesh, msg);
    return 0;
}

int bake_uv_dry_verdict(const char *cmd, const char *mesh, const soak_image *exposure, const soak_uv_stats *s,
                        const bake_uv_opts *u)
{
    size_t n = (size_t)exposure->width * exposure->height * exposure->channels;
    for (size_t i = 0; i < n; ++i)
        if (exposure->pixels[i] > 0.0f) return 0;
    if (s->covered == 0) return 0; /* bake_uv_verdict's empty map */
    const char *why = "no covered texel sees the sky (exposure 0 on all %lld): is --up the mesh's up axis?";
    char msg[256];
    snprintf(msg, sizeof msg, why, s->covered);
    if (u->strict) {
        cli_error(cmd, "%s: %s; --strict: nothing written", mesh, msg);
        return 1;
    }
    fprintf(stderr, "soak %s: warning: %s: %s\n", cmd, mesh, msg);
    return 0;
}

void bake_uv_report(const char *label, const soak_uv_stats *s)
{
    char line[512];
    soak_uv_stats_line(s, line, sizeof line);
    printf("%s: uv: %s\n", label, line);
}

int bake_uv_is_udim(const char *path) { return path && strstr(path, "<UDIM>") != NULL; }

soak_status bake_uv_tile_path(const char *path, int tile, char *out, size_t n)
{
    const char *at = strstr(path, "<UDIM>");
    if (!at) return SOAK_ERR_ARG;
    int w = snprintf(out, n, "%.*s%d%s", (int)(at - path), path, tile, at + 6);
    return w >= 0 && (size_t)w < n ? SOAK_OK : SOAK_ERR_ARG;
}

void bake_uv_formats_help(FILE *out)
{
    fprintf(out, "\n");
    soak_mesh_formats_print(out);
}
