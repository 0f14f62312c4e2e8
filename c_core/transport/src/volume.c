/* Voxel grids of medium parameters (soak/volume.h): allocation, channel
 * names, validation and the linear row lookup. */
#include "soak/volume.h"

#include <stdlib.h>
#include <string.h>

#include "soak/hg.h"

static const char *const channel_names[SOAK_VOL_NCHANNELS] = {
    "sigma_s_r", "sigma_s_g", "sigma_s_b", "sigma_a_r", "sigma_a_g", "sigma_a_b", "g1", "g2", "w", "wetness",
};

const char *soak_volume_channel_name(int channel)
{
    return channel >= 0 && channel < SOAK_VOL_NCHANNELS ? channel_names[channel] : NULL;
}

soak_status soak_vol_medium_validate(const soak_vol_medium *m)
{
    if (!m) return SOAK_ERR_NULL;
    for (int c = 0; c < 3; ++c)
        if (!soak_in_range(soak_rgb_at(m->sigma_s, c), 0.0, SOAK_VOL_SIGMA_MAX) ||
            !soak_in_range(soak_rgb_at(m->sigma_a, c), 0.0, SOAK_VOL_SIGMA_MAX))
            return SOAK_ERR_ARG;
    soak_hg2 hg = {m->g1, m->g2, m->w};
    return soak_in_range(hg.g1, -SOAK_HG_G_MAX, SOAK_HG_G_MAX) && soak_in_range(hg.g2, -SOAK_HG_G_MAX, SOAK_HG_G_MAX) &&
                   soak_in_range(hg.w, 0.0, 1.0)
               ? SOAK_OK
               : SOAK_ERR_ARG;
}

soak_status soak_volume_alloc(soak_volume *v, int nx, int ny, int nz, const double size[3])
{
    if (!v || !size) return SOAK_ERR_NULL;
    memset(v, 0, sizeof *v);
    if (!(nx >= 1 && nx <= SOAK_VOLUME_MAX_DIM && ny >= 1 && ny <= SOAK_VOLUME_MAX_DIM && nz >= 1 &&
          nz <= SOAK_VOLUME_MAX_DIM))
        return SOAK_ERR_ARG;
    for (int a = 0; a < 3; ++a)
        if (!(size[a] > 0.0 && soak_is_finite(size[a]))) return SOAK_ERR_ARG;
    size_t n = (size_t)nx * (size_t)ny * (size_t)nz;
    if (n > ((size_t)1 << 31) / SOAK_VOL_NCHANNELS) return SOAK_ERR_ARG; /* 8 GiB of floats is a typo, not a bake */
    v->data = calloc(n * SOAK_VOL_NCHANNELS, sizeof(float));
    if (!v->data) return SOAK_ERR_NOMEM;
    v->nx = nx;
    v->ny = ny;
    v->nz = nz;
    memcpy(v->size, size, sizeof v->size);
    return SOAK_OK;
}

void soak_volume_free(soak_volume *v)
{
    if (!v) return;
    free(v->data);
    memset(v, 0, sizeof *v);
}

soak_vol_medium soak_vol_rows_eval(const soak_vol_medium *rows, int n_rows, double w)
{
    double x = (w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w)) * (n_rows - 1);
    int i = (int)x;
    if (i >= n_rows - 1) i = n_rows - 2;
    double t = x - i, u = 1.0 - t;
    const soak_vol_medium *a = &rows[i], *b = &rows[i + 1];
    soak_vol_medium m;
    m.sigma_s = soak_rgb3(u * a->sigma_s.r + t * b->sigma_s.r, u * a->sigma_s.g + t * b->sigma_s.g,
                          u * a->sigma_s.b + t * b->sigma_s.b);
    m.sigma_a = soak_rgb3(u * a->sigma_a.r + t * b->sigma_a.r, u * a->sigma_a.g + t * b->sigma_a.g,
                          u * a->sigma_a.b + t * b->sigma_a.b);
    m.g1 = u * a->g1 + t * b->g1;
    m.g2 = u * a->g2 + t * b->g2;
    m.w = u * a->w + t * b->w;
    return m;
}
