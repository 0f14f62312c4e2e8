/* A df3 parameter volume rendered by POV-Ray: a unit media box, absorbing
 * only, left half (x < 0.5) absorption sigma, right half 0, seen by an
 * orthographic camera along z in front of a white background. Each pixel is
 * the transmittance exp(-sigma * density(x) * 1), where density(x) is the
 * trilinear interpolant of the voxel centres (i + 0.5)/N: 1 up to the last
 * wet centre, 0 from the first dry one, linear between. This checks the
 * df3 bytes, the per-channel scale from the sidecar, the half-voxel
 * transform and the replicated border (no wrap at x = 0). SKIPPED without
 * povray on PATH. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "check.h"
#include "soak/bake_volume.h"
#include "soak/image.h"

#define NX 8
#define SIGMA 1.5

static double left_half(void *ctx, double x, double y, double z)
{
    (void)ctx, (void)y, (void)z;
    return x < 0.5 ? 1.0 : 0.0;
}

static double scale_from_sidecar(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NAN;
    char buf[65536];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    cJSON *root = cJSON_Parse(buf);
    cJSON *c = cJSON_GetObjectItem(cJSON_GetObjectItem(cJSON_GetObjectItem(root, "channels"), "sigma_a_r"), "scale");
    double s = cJSON_IsNumber(c) ? c->valuedouble : NAN;
    cJSON_Delete(root);
    return s;
}

int main(void)
{
    if (system("command -v povray > /dev/null 2>&1") != 0) {
        check_skip("POV-Ray render of a df3 media box", "povray not on PATH");
        return check_finish();
    }
    const char *dir = "test_tmp/bake_volume_pov";
    mkdir("test_tmp", 0755);
    mkdir(dir, 0755);
    soak_volume v;
    double size[3] = {1, 1, 1};
    soak_volume_alloc(&v, NX, 2, 2, size);
    soak_vol_medium dry = {{0, 0, 0}, {0, 0, 0}, 0, 0, 0}, wet = {{0, 0, 0}, {SIGMA, SIGMA, SIGMA}, 0, 0, 0};
    soak_volume_source src = {NULL, 0, 0, left_half, NULL};
    char err[512] = "";
    check_status("bake", soak_volume_bake(&v, (soak_vol_medium[2]){dry, wet}, 2, &src, NULL), SOAK_OK);
    check_status("write df3", soak_volume_write_df3(&v, "test_tmp/bake_volume_pov/vol", 16, err, sizeof err), SOAK_OK);
    soak_volume_free(&v);
    double scale = scale_from_sidecar("test_tmp/bake_volume_pov/vol_df3.json");
    check_close("sidecar scale of sigma_a_r = sigma", scale, SIGMA, 1e-12);

    FILE *f = fopen("test_tmp/bake_volume_pov/scene.pov", "w");
    fprintf(f, "#version 3.7;\n"
               "global_settings { assumed_gamma 1.0 }\n"
               "#include \"vol.inc\"\n"
               "camera { orthographic location <0.5, 0.5, -1> direction z right x up y }\n"
               "background { rgb 1 }\n"
               "box { 0, 1 hollow pigment { rgbt 1 } finish { ambient 0 diffuse 0 }\n"
               "  interior { media { method 3 intervals 1 samples 10, 10\n"
               "    absorption vol_sigma_a_r_scale vol_density(vol_sigma_a_r_file) } } }\n");
    fclose(f);
    int rc = system("cd test_tmp/bake_volume_pov && povray +Iscene.pov +Oout.exr +FE +W64 +H8 -D -V -GA +WT1 "
                    "> povray.log 2>&1");
    if (!check_true("povray exit status 0", rc == 0)) return check_finish();
    soak_image img;
    if (!check_status("read render", soak_image_read("test_tmp/bake_volume_pov/out.exr", &img, err, sizeof err), SOAK_OK))
        return check_finish();

    /* Analytic transmittance per pixel column of the middle row. */
    double worst = 0.0, left = 0.0, right = 0.0, edge = 0.0;
    int nl = 0, nr = 0;
    double c_wet = (NX / 2 - 0.5) / NX, c_dry = (NX / 2 + 0.5) / NX; /* last wet, first dry centre */
    for (int x = 0; x < img.width; ++x) {
        double px = (x + 0.5) / img.width;
        double d = px <= c_wet ? 1.0 : (px >= c_dry ? 0.0 : (c_dry - px) / (c_dry - c_wet));
        double want = exp(-scale * d);
        double got = img.pixels[((size_t)(img.height / 2) * img.width + x) * img.channels];
        worst = fmax(worst, fabs(got - want));
        if (px < 0.35) {
            left += got;
            ++nl;
        }
        if (px > 0.65) {
            right += got;
            ++nr;
        }
        if (x == 0) edge = got;
    }
    check_close("left half transmittance vs exp(-sigma L)", left / nl, exp(-SIGMA), 2e-3);
    check_close("right half transmittance vs 1", right / nr, 1.0, 2e-3);
    check_close("edge column x = 0.5/64 (no wrap from the dry side)", edge, exp(-SIGMA), 2e-3);
    check_close("every column vs the interpolated analytic value, max |diff|", worst, 0.0, 3e-3);
    soak_image_free(&img);
    return check_finish();
}
