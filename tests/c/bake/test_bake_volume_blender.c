/* The OpenVDB volume through Blender's volume import (an independent
 * OpenVDB reader): the grid names and types, each grid's index-to-object
 * matrix (voxel size = box size / dims, voxel (0,0,0) centred half a voxel
 * inside the box, so the cells cover exactly [0, size]) and the object's
 * bounds (Blender reports voxel-centre bounds rounded up to its 8^3 leaf
 * nodes: min = first voxel centre, max >= last voxel centre). SKIPPED
 * without blender on PATH or without OpenVDB in libsoak. */
#define _XOPEN_SOURCE 700
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "check.h"
#include "soak/bake_volume.h"

static const char *grids[] = {"density", "sigma_s", "sigma_a", "sigma_s_r", "sigma_a_b", "g1", "g2", "w", "wetness"};

int main(void)
{
    if (!soak_volume_have_vdb()) {
        check_skip("Blender volume import", "libsoak built without OpenVDB");
        return check_finish();
    }
    if (system("command -v blender > /dev/null 2>&1") != 0) {
        check_skip("Blender volume import", "blender not on PATH");
        return check_finish();
    }
    mkdir("test_tmp", 0755);
    mkdir("test_tmp/bake_volume_blender", 0755);
    char dir[PATH_MAX];
    if (!realpath("test_tmp/bake_volume_blender", dir)) return 1;

    const int n[3] = {8, 4, 5};
    const double size[3] = {2.0, 1.0, 0.5};
    soak_volume v;
    soak_volume_alloc(&v, n[0], n[1], n[2], size);
    soak_vol_medium dry = {{1, 1, 1}, {0.1, 0.1, 0.1}, 0.1, -0.1, 0.5}, wet = {{2, 2, 2}, {1.5, 1, 0.5}, 0.8, -0.1, 0.2};
    soak_volume_source src = {NULL, 1.0, 0.25, NULL, NULL};
    soak_volume_bake(&v, (soak_vol_medium[2]){dry, wet}, 2, &src, NULL);
    char vdb[PATH_MAX + 32], py[PATH_MAX + 32], out[PATH_MAX + 32], cmd[3 * PATH_MAX], err[512] = "";
    snprintf(vdb, sizeof vdb, "%s/vol.vdb", dir);
    snprintf(py, sizeof py, "%s/read.py", dir);
    snprintf(out, sizeof out, "%s/result.json", dir);
    check_status("write vdb", soak_volume_write_vdb(&v, vdb, err, sizeof err), SOAK_OK);
    soak_volume_free(&v);
    remove(out);

    FILE *f = fopen(py, "w");
    fprintf(f,
            "import bpy, json\n"
            "bpy.ops.object.volume_import(filepath=%s%s%s)\n"
            "obj = bpy.context.selected_objects[0]\n"
            "vol = obj.data\n"
            "assert vol.grids.load(), vol.grids.error_message\n"
            "ev = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())\n"
            "res = {'grids': {g.name: {'type': g.data_type, 'matrix': [list(r) for r in g.matrix_object]}\n"
            "                 for g in vol.grids},\n"
            "       'bound_box': [list(c) for c in ev.bound_box]}\n"
            "json.dump(res, open(%s%s%s, 'w'))\n",
            "'", vdb, "'", "'", out, "'");
    fclose(f);
    snprintf(cmd, sizeof cmd,
             "blender -b --factory-startup --python-exit-code 1 --python '%s' > '%s/blender.log' 2>&1", py, dir);
    if (!check_true("blender exit status 0", system(cmd) == 0)) return check_finish();

    f = fopen(out, "rb");
    static char buf[1 << 16];
    size_t len = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
    if (f) fclose(f);
    buf[len] = 0;
    cJSON *root = cJSON_Parse(buf);
    if (!check_true("result JSON", root != NULL)) return check_finish();
    cJSON *gs = cJSON_GetObjectItem(root, "grids");
    int names_ok = 1, types_ok = 1;
    double worst = 0.0;
    for (size_t g = 0; g < sizeof grids / sizeof grids[0]; ++g) {
        cJSON *o = cJSON_GetObjectItem(gs, grids[g]);
        if (!o) {
            printf("missing grid %s\n", grids[g]);
            names_ok = 0;
            continue;
        }
        if (strcmp(cJSON_GetObjectItem(o, "type")->valuestring, "FLOAT") != 0) types_ok = 0;
        cJSON *m = cJSON_GetObjectItem(o, "matrix");
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) {
                double got = cJSON_GetArrayItem(cJSON_GetArrayItem(m, r), c)->valuedouble;
                double want = c == r ? size[r] / n[r] : (c == 3 ? 0.5 * size[r] / n[r] : 0.0);
                worst = fmax(worst, fabs(got - want));
            }
    }
    check_true("Blender lists every grid by name", names_ok);
    check_true("every grid is FLOAT", types_ok);
    check_close("index-to-object matrices vs size/dims and half-voxel offset, max |diff|", worst, 0.0, 1e-6);
    cJSON *bb = cJSON_GetObjectItem(root, "bound_box");
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int c = 0; c < 8; ++c)
        for (int a = 0; a < 3; ++a) {
            double x = cJSON_GetArrayItem(cJSON_GetArrayItem(bb, c), a)->valuedouble;
            lo[a] = fmin(lo[a], x);
            hi[a] = fmax(hi[a], x);
        }
    double worst_lo = 0.0;
    int hi_ok = 1;
    for (int a = 0; a < 3; ++a) {
        double h = size[a] / n[a];
        worst_lo = fmax(worst_lo, fabs(lo[a] - 0.5 * h));
        if (!(hi[a] >= (n[a] - 0.5) * h - 1e-6 && hi[a] <= (8 * ((n[a] + 7) / 8) - 0.5) * h + 1e-6)) hi_ok = 0;
    }
    check_close("bounds min = first voxel centre, max |diff|", worst_lo, 0.0, 1e-6);
    check_true("bounds max between the last voxel centre and its leaf node end", hi_ok);
    cJSON_Delete(root);
    return check_finish();
}
