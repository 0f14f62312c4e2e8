// OpenVDB writer/reader for parameter volumes (grid list and transform in
// soak/bake_volume.h). Compiled against OpenVDB only when the build defines
// SOAK_HAVE_OPENVDB (the library needs -lopenvdb -ltbb -lImath and Boost
// headers); otherwise the entry points report SOAK_ERR_UNSUPPORTED.
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" {
#include "soak/volume.h"
#include "soak/staged_files.h"
}

#ifdef SOAK_HAVE_OPENVDB
#include <openvdb/openvdb.h>

namespace {

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg.c_str());
}

openvdb::math::Transform::Ptr box_transform(const soak_volume *v)
{
    openvdb::Vec3d vox(v->size[0] / v->nx, v->size[1] / v->ny, v->size[2] / v->nz);
    openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
    m.preScale(vox);
    // Index (i,j,k) is the voxel centre ((i+0.5) dx, ...): the cells cover the box.
    m.postTranslate(vox * 0.5);
    return openvdb::math::Transform::createLinearTransform(m);
}

// Every voxel is set active (also zeros) so the active bounding box is the
// whole volume box; constant regions collapse into tiles.
openvdb::FloatGrid::Ptr make_grid(const soak_volume *v, const std::string &name,
                                  const openvdb::math::Transform::Ptr &xf, const std::vector<float> &values,
                                  bool fog)
{
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName(name);
    grid->setTransform(xf);
    grid->setGridClass(fog ? openvdb::GRID_FOG_VOLUME : openvdb::GRID_UNKNOWN);
    auto acc = grid->getAccessor();
    for (int k = 0; k < v->nz; ++k)
        for (int j = 0; j < v->ny; ++j)
            for (int i = 0; i < v->nx; ++i)
                acc.setValueOn(openvdb::Coord(i, j, k), values[soak_volume_index(v, i, j, k)]);
    grid->tree().prune();
    grid->insertMeta("soak_units", openvdb::StringMetadata("per length unit of the volume box"));
    return grid;
}

std::vector<float> plane_copy(const soak_volume *v, int c)
{
    const float *p = soak_volume_plane(v, c);
    return std::vector<float>(p, p + soak_volume_count(v));
}

} // namespace

extern "C" int soak_volume_have_vdb(void)
{
    return 1;
}

// A written file read back in full: io::File does not report every failed
// write (a full disk can leave it short without an exception).
static void read_back(const char *tmp, size_t n_grids)
{
    openvdb::io::File in(tmp);
    in.open(false);
    openvdb::GridPtrVecPtr grids = in.getGrids();
    in.close();
    if (!grids || grids->size() != n_grids) throw std::runtime_error("file incomplete after writing");
}

extern "C" soak_status soak_volume_stage_vdb(soak_staged *stage, const soak_volume *v, const char *path, char *err,
                                             size_t errlen)
{
    if (!stage || !v || !v->data || !path) return SOAK_ERR_NULL;
    const char *tmp = nullptr;
    soak_status st = soak_staged_add(stage, path, &tmp, err, errlen);
    if (st != SOAK_OK) return st;
    try {
        openvdb::initialize();
        auto xf = box_transform(v);
        size_t n = soak_volume_count(v);
        openvdb::GridPtrVec grids;
        std::vector<float> mean_s(n), mean_a(n), density(n);
        const float *s[3], *a[3];
        for (int c = 0; c < 3; ++c) {
            s[c] = soak_volume_plane(v, SOAK_VOL_SIGMA_S_R + c);
            a[c] = soak_volume_plane(v, SOAK_VOL_SIGMA_A_R + c);
        }
        for (size_t i = 0; i < n; ++i) {
            mean_s[i] = (float)(((double)s[0][i] + s[1][i] + s[2][i]) / 3.0);
            mean_a[i] = (float)(((double)a[0][i] + a[1][i] + a[2][i]) / 3.0);
            density[i] = mean_s[i] + mean_a[i];
        }
        grids.push_back(make_grid(v, "density", xf, density, true));
        grids.push_back(make_grid(v, "sigma_s", xf, mean_s, true));
        grids.push_back(make_grid(v, "sigma_a", xf, mean_a, true));
        for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c)
            grids.push_back(make_grid(v, soak_volume_channel_name(c), xf, plane_copy(v, c), c <= SOAK_VOL_SIGMA_A_B));
        openvdb::io::File file(tmp);
        file.write(grids);
        file.close();
        read_back(tmp, grids.size());
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path) + ": OpenVDB write failed: " + e.what());
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

extern "C" soak_status soak_volume_read_vdb_grid(const char *path, const char *grid, int nx, int ny, int nz,
                                                 float *values, double voxel_size[3], double origin[3], char *err,
                                                 size_t errlen)
{
    if (!path || !grid || !values || !voxel_size || !origin) return SOAK_ERR_NULL;
    if (!(nx >= 1 && ny >= 1 && nz >= 1)) return SOAK_ERR_ARG;
    try {
        openvdb::initialize();
        openvdb::io::File file(path);
        file.open();
        if (!file.hasGrid(grid)) {
            set_err(err, errlen, std::string(path) + ": no grid named '" + grid + "'");
            file.close();
            return SOAK_ERR_NOT_FOUND;
        }
        auto base = file.readGrid(grid);
        file.close();
        auto fg = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
        if (!fg) {
            set_err(err, errlen, std::string(path) + ": grid '" + grid + "' is not a float grid");
            return SOAK_ERR_PARSE;
        }
        auto acc = fg->getConstAccessor();
        size_t idx = 0;
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) values[idx++] = acc.getValue(openvdb::Coord(i, j, k));
        openvdb::Vec3d vs = fg->voxelSize();
        openvdb::Vec3d o = fg->indexToWorld(openvdb::Vec3d(0, 0, 0));
        for (int a = 0; a < 3; ++a) {
            voxel_size[a] = vs[a];
            origin[a] = o[a];
        }
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path) + ": OpenVDB read failed: " + e.what());
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

#else

extern "C" int soak_volume_have_vdb(void)
{
    return 0;
}

extern "C" soak_status soak_volume_stage_vdb(soak_staged *stage, const soak_volume *v, const char *path, char *err,
                                             size_t errlen)
{
    if (!stage || !v || !path) return SOAK_ERR_NULL;
    if (err && errlen) std::snprintf(err, errlen, "%s: this build of libsoak has no OpenVDB support", path);
    return SOAK_ERR_UNSUPPORTED;
}

extern "C" soak_status soak_volume_read_vdb_grid(const char *path, const char *grid, int nx, int ny, int nz,
                                                 float *values, double voxel_size[3], double origin[3], char *err,
                                                 size_t errlen)
{
    (void)grid, (void)nx, (void)ny, (void)nz, (void)values, (void)voxel_size, (void)origin;
    if (!path) return SOAK_ERR_NULL;
    if (err && errlen) std::snprintf(err, errlen, "%s: this build of libsoak has no OpenVDB support", path);
    return SOAK_ERR_UNSUPPORTED;
}

#endif

extern "C" soak_status soak_volume_write_vdb(const soak_volume *v, const char *path, char *err, size_t errlen)
{
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = soak_volume_stage_vdb(&stage, v, path, err, errlen);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}
