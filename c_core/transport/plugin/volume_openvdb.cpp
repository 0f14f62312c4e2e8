// libsoak_vdb.so: OpenVDB writer/reader for parameter volumes (the table of
// transport/src/vdb_plugin.h; grid list and transform in soak/volume.h).
// Loaded by transport/src/volume_vdb.c on a command's first .vdb. Needs
// -lopenvdb -ltbb -lImath and Boost headers. Calls nothing of libsoak; no
// exception leaves the module.
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

#include <openvdb/openvdb.h>

extern "C" {
#include "vdb_plugin.h"
}

namespace {

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg.c_str());
}

openvdb::math::Transform::Ptr box_transform(const double voxel[3])
{
    openvdb::Vec3d vox(voxel[0], voxel[1], voxel[2]);
    openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
    m.preScale(vox);
    // Index (i,j,k) is the voxel centre ((i+0.5) dx, ...): the cells cover the box.
    m.postTranslate(vox * 0.5);
    return openvdb::math::Transform::createLinearTransform(m);
}

// Every voxel is set active (also zeros) so the active bounding box is the
// whole volume box; constant regions collapse into tiles.
openvdb::FloatGrid::Ptr make_grid(const int dims[3], const soak_vdb_grid &g, const openvdb::math::Transform::Ptr &xf)
{
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName(g.name);
    grid->setTransform(xf);
    grid->setGridClass(g.fog ? openvdb::GRID_FOG_VOLUME : openvdb::GRID_UNKNOWN);
    auto acc = grid->getAccessor();
    size_t idx = 0;
    for (int k = 0; k < dims[2]; ++k)
        for (int j = 0; j < dims[1]; ++j)
            for (int i = 0; i < dims[0]; ++i) acc.setValueOn(openvdb::Coord(i, j, k), g.values[idx++]);
    grid->tree().prune();
    grid->insertMeta("soak_units", openvdb::StringMetadata("per length unit of the volume box"));
    return grid;
}

// A written file read back in full: io::File does not report every failed
// write (a full disk can leave it short without an exception).
void read_back(const char *tmp, size_t n_grids)
{
    openvdb::io::File in(tmp);
    in.open(false);
    openvdb::GridPtrVecPtr grids = in.getGrids();
    in.close();
    if (!grids || grids->size() != n_grids) throw std::runtime_error("file incomplete after writing");
}

soak_status write_grids(const char *tmp, const char *path, const int dims[3], const double voxel[3],
                        const soak_vdb_grid *grids, int n_grids, char *err, size_t errlen)
{
    try {
        openvdb::initialize();
        auto xf = box_transform(voxel);
        openvdb::GridPtrVec out;
        for (int g = 0; g < n_grids; ++g) out.push_back(make_grid(dims, grids[g], xf));
        openvdb::io::File file(tmp);
        file.write(out);
        file.close();
        read_back(tmp, out.size());
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path) + ": OpenVDB write failed: " + e.what());
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

soak_status read_grid(const char *path, const char *grid, int nx, int ny, int nz, float *values,
                      double voxel_size[3], double origin[3], char *err, size_t errlen)
{
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

} // namespace

extern "C" __attribute__((visibility("default"))) const soak_vdb_plugin soak_vdb_plugin_v1 = {write_grids, read_grid};
