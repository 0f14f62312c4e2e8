// libsoak_image.so: OpenImageIO behind soak/image.h (the table of
// core/src/image_plugin.h). Loaded by core/src/image_plugin.c on a command's first
// image, so that commands without images do not map OpenImageIO's 260
// libraries. Calls nothing of libsoak; no exception leaves the module.
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/filesystem.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

extern "C" {
#include "image_plugin.h"
}

using namespace OIIO;

namespace {

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg.c_str());
}

TypeDesc pixel_type_for(const std::string &ext, soak_pixel_type t)
{
    switch (t) {
    case SOAK_PIXEL_HALF: return TypeDesc::HALF;
    case SOAK_PIXEL_FLOAT: return TypeDesc::FLOAT;
    case SOAK_PIXEL_UINT16: return TypeDesc::UINT16;
    case SOAK_PIXEL_UINT8: return TypeDesc::UINT8;
    default: break;
    }
    if (ext == "exr") return TypeDesc::HALF;
    if (ext == "hdr") return TypeDesc::FLOAT;
    if (ext == "jpg" || ext == "jpeg") return TypeDesc::UINT8;
    return TypeDesc::UINT16;
}

float srgb_encode(float v)
{
    if (!(v > 0.0f)) return 0.0f;
    if (v >= 1.0f) return 1.0f;
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

// The reader path's extension names, opened on path, and no other:
// ImageInput::open(path) tries every reader OIIO has after the named one
// refuses the file (its DICOM reader walked 256 MiB of zeros for 18.5 s).
std::unique_ptr<ImageInput> open_named_reader(const char *path, char *err, size_t errlen)
{
    auto in = ImageInput::create(path, false);
    if (!in) {
        set_err(err, errlen, std::string(path) + ": cannot read image: no reader for this extension: " + OIIO::geterror());
        return nullptr;
    }
    ImageSpec spec;
    if (!in->open(path, spec)) {
        std::string why = in->geterror();
        set_err(err, errlen, std::string(path) + ": cannot read image as " + in->format_name() + ": " +
                                 (why.empty() ? std::string("not a valid file") : why));
        return nullptr;
    }
    return in;
}

// soak/image.h's limits on the header of an open reader.
soak_status check_spec(const char *path, const ImageSpec &spec, long long payload_bytes, char *err, size_t errlen)
{
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) {
        set_err(err, errlen, std::string(path) + ": the header declares no pixels (" + std::to_string(spec.width) + "x" +
                                 std::to_string(spec.height) + "x" + std::to_string(spec.nchannels) + ")");
        return SOAK_ERR_ARG;
    }
    if (spec.width > SOAK_IMAGE_MAX_SIDE || spec.height > SOAK_IMAGE_MAX_SIDE) {
        set_err(err, errlen, std::string(path) + ": a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                 " image is larger than " + std::to_string(SOAK_IMAGE_MAX_SIDE) +
                                 " pixels on a side (the limit of every command)");
        return SOAK_ERR_ARG;
    }
    int ch = spec.nchannels < 4 ? spec.nchannels : 4;
    if (spec.depth > 1) {
        set_err(err, errlen, std::string(path) + ": volume images are not supported");
        return SOAK_ERR_UNSUPPORTED;
    }
    double bytes = (double)spec.width * spec.height * ch * sizeof(float);
    if (bytes > SOAK_IMAGE_MAX_BYTES) {
        set_err(err, errlen, std::string(path) + ": a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                 " image needs " + std::to_string((long long)(bytes / 1048576)) +
                                 " MiB as float pixels; the limit is " +
                                 std::to_string((long long)(SOAK_IMAGE_MAX_BYTES / 1048576)) + " MiB");
        return SOAK_ERR_ARG;
    }
    if (bytes > SOAK_IMAGE_FREE_BYTES && bytes > SOAK_IMAGE_MAX_RATIO * (double)payload_bytes) {
        set_err(err, errlen, std::string(path) + ": the header claims " + std::to_string(spec.width) + "x" +
                                 std::to_string(spec.height) + "x" + std::to_string(ch) + " pixels (" +
                                 std::to_string((long long)(bytes / 1048576)) + " MiB as float) from " +
                                 std::to_string(payload_bytes) + " bytes of compressed pixel data: more than " +
                                 std::to_string((int)SOAK_IMAGE_MAX_RATIO) +
                                 " float bytes per byte of pixel data above " +
                                 std::to_string((long long)(SOAK_IMAGE_FREE_BYTES / 1048576)) +
                                 " MiB (a decompression bomb or a corrupt header)");
        return SOAK_ERR_ARG;
    }
    return SOAK_OK;
}

// The pixels as float, a band of rows at a time, to the sink: the reader's
// own buffers stay native (8-bit PNG: a quarter of the floats).
soak_status read_to_sink(const char *path, long long payload_bytes, const soak_image_sink *sink, char *err,
                         size_t errlen)
{
    auto in = open_named_reader(path, err, errlen);
    if (!in) return SOAK_ERR_IO;
    const ImageSpec spec = in->spec();
    soak_status st = check_spec(path, spec, payload_bytes, err, errlen);
    if (st != SOAK_OK) return st;
    int ch = spec.nchannels < 4 ? spec.nchannels : 4;
    if (sink->begin(sink->ctx, spec.width, spec.height, ch) != 0) return SOAK_ERR_IO;
    size_t row = (size_t)spec.width * ch;
    // Tiled files (.tx) are read whole: read_scanlines on them raised
    // SIGFPE in OpenImageIO 2.4.
    int band = spec.tile_width > 0 ? spec.height
                                   : (int)std::max<size_t>(1, ((size_t)4 << 20) / (row * sizeof(float)));
    std::vector<float> buf((size_t)std::min(band, spec.height) * row);
    for (int y = 0; y < spec.height; y += band) {
        int n = std::min(band, spec.height - y);
        bool ok = band == spec.height
                      ? in->read_image(0, 0, 0, ch, TypeDesc::FLOAT, buf.data())
                      : in->read_scanlines(0, 0, spec.y + y, spec.y + y + n, 0, 0, ch, TypeDesc::FLOAT, buf.data());
        if (!ok) {
            set_err(err, errlen, std::string(path) + ": truncated or unreadable image data: " + in->geterror());
            return SOAK_ERR_IO;
        }
        if (sink->rows(sink->ctx, buf.data(), (size_t)n * row) != 0) return SOAK_ERR_IO;
    }
    in->close();
    return SOAK_OK;
}

// Encodes img in the format named by path's extension into memory (every
// writer OIIO 2.4 has for our formats accepts an I/O proxy), so that every
// byte reaches the disk through one checked write.
soak_status encode(const std::string &path, const ImageSpec &spec, const float *pixels, std::vector<unsigned char> &out,
                   char *err, size_t errlen)
{
    auto w = ImageOutput::create(path);
    if (!w) {
        set_err(err, errlen, path + ": unsupported output type: " + OIIO::geterror());
        return SOAK_ERR_ARG;
    }
    if (!w->supports("ioproxy")) {
        set_err(err, errlen, path + ": this output type cannot be written safely (no I/O proxy)");
        return SOAK_ERR_UNSUPPORTED;
    }
    Filesystem::IOVecOutput proxy(out);
    w->set_ioproxy(&proxy);
    if (!w->open(path, spec) || !w->write_image(TypeDesc::FLOAT, pixels) || !w->close()) {
        set_err(err, errlen, path + ": cannot encode image: " + w->geterror());
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

void convert_pixels(const soak_image *img, const soak_image_write_opts &o, bool integer, float *dst)
{
    size_t n = (size_t)img->width * img->height * img->channels;
    for (size_t i = 0; i < n; ++i) {
        float v = img->pixels[i];
        if (!std::isfinite(v)) v = 0.0f;
        if (o.tone == SOAK_TONE_SRGB && (img->channels < 4 || (i % 4) != 3)) v = srgb_encode(v);
        if (integer) v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
        dst[i] = v;
    }
}

soak_status encode_image(const char *path, const char *ext_c, const soak_image *img, const soak_image_write_opts *opts,
                         unsigned char **bytes_out, size_t *n_out, char *err, size_t errlen)
{
    const std::string ext(ext_c);
    const soak_image_write_opts o = *opts;
    TypeDesc type = pixel_type_for(ext, o.pixel_type);
    ImageSpec spec(img->width, img->height, img->channels, type);
    if (o.tone == SOAK_TONE_SRGB) spec.attribute("oiio:ColorSpace", "sRGB");
    else spec.attribute("oiio:ColorSpace", "Linear");
    if (ext == "exr") spec.attribute("compression", "zip");
    // Our four-channel maps are data with a straight alpha (ripples: normal
    // and height). Without this OIIO takes RGB as premultiplied and divides
    // it by alpha when writing PNG (unpremultiplied by format), which made
    // the ripples' stored normals up to 0.73 too long (issue 48).
    if (img->channels == 4) spec.attribute("oiio:UnassociatedAlpha", 1);
    // An empty DateTime keeps OIIO's EXR and TIFF writers from stamping the
    // clock into the file: the same pixels give the same bytes.
    spec.attribute("DateTime", "");
    bool integer = type.basetype == TypeDesc::UINT16 || type.basetype == TypeDesc::UINT8;
    std::vector<float> px((size_t)img->width * img->height * img->channels);
    convert_pixels(img, o, integer, px.data());
    std::vector<unsigned char> bytes;
    soak_status st = encode(path, spec, px.data(), bytes, err, errlen);
    if (st != SOAK_OK) return st;
    *bytes_out = (unsigned char *)std::malloc(bytes.size() ? bytes.size() : 1);
    if (!*bytes_out) return SOAK_ERR_NOMEM;
    std::memcpy(*bytes_out, bytes.data(), bytes.size());
    *n_out = bytes.size();
    return SOAK_OK;
}

// Reads every level of the texture at tmp back, which fails on a file cut
// short by a failed write that the TIFF writer did not report.
static bool texture_reads_back(const char *tmp, int levels, std::string &why)
{
    auto in = ImageInput::open(tmp);
    if (!in) {
        why = OIIO::geterror();
        return false;
    }
    std::vector<float> px;
    int n = 0;
    for (; in->seek_subimage(0, n); ++n) { // a texture's levels read as MIP levels
        const ImageSpec &s = in->spec();
        px.resize((size_t)s.width * s.height * s.nchannels);
        if (!in->read_image(0, n, 0, s.nchannels, TypeDesc::FLOAT, px.data())) {
            why = in->geterror();
            return false;
        }
    }
    if (n != levels) why = "texture has " + std::to_string(n) + " of its " + std::to_string(levels) + " levels";
    return n == levels;
}

// Every tile from a zero-padded buffer: write_image leaves the padding of
// partial edge tiles uninitialised, so the same texture got different bytes.
static bool write_tiles(ImageOutput &w, const ImageSpec &spec, const float *px)
{
    const int tw = spec.tile_width, th = spec.tile_height, ch = spec.nchannels;
    std::vector<float> tile((size_t)tw * th * ch);
    for (int y0 = 0; y0 < spec.height; y0 += th)
        for (int x0 = 0; x0 < spec.width; x0 += tw) {
            std::fill(tile.begin(), tile.end(), 0.0f);
            for (int y = y0; y < std::min(y0 + th, spec.height); ++y)
                std::memcpy(&tile[((size_t)(y - y0) * tw) * ch], px + ((size_t)y * spec.width + x0) * ch,
                            (size_t)(std::min(x0 + tw, spec.width) - x0) * ch * sizeof(float));
            if (!w.write_tile(x0, y0, 0, TypeDesc::FLOAT, tile.data())) return false;
        }
    return true;
}

// A mip-mapped, tiled TIFF texture as maketx makes it ("Plain Texture",
// 64x64 tiles, each level half the previous, lanczos3 filtered; TIFF holds
// the levels as subimages, which readers take as MIP levels). OIIO's
// make_texture writes through its own temporary file next to the target
// (which an interrupt would leave behind), and OIIO 2.4's TIFF writer loses
// every subimage but the last through an in-memory I/O proxy, so the levels
// are written here to the staged file's path and read back.
static soak_status write_tx(const char *tmp, const std::string &path, const soak_image *img, char *err,
                            size_t errlen)
{
    auto w = ImageOutput::create("tiff");
    if (!w) {
        set_err(err, errlen, path + ": cannot make texture: " + OIIO::geterror());
        return SOAK_ERR_UNSUPPORTED;
    }
    std::vector<ImageSpec> specs;
    for (int x = img->width, y = img->height;; x = std::max(1, x / 2), y = std::max(1, y / 2)) {
        ImageSpec spec(x, y, img->channels, TypeDesc::HALF);
        spec.tile_width = spec.tile_height = 64;
        spec.attribute("textureformat", "Plain Texture");
        spec.attribute("wrapmodes", "black,black");
        spec.attribute("oiio:ColorSpace", "Linear");
        spec.attribute("compression", "zip");
        spec.attribute("DateTime", "");
        specs.push_back(spec);
        if (x == 1 && y == 1) break;
    }
    ImageBuf level(ImageSpec(img->width, img->height, img->channels, TypeDesc::FLOAT));
    std::memcpy(level.localpixels(), img->pixels, (size_t)img->width * img->height * img->channels * sizeof(float));
    bool ok = w->open(tmp, (int)specs.size(), specs.data());
    for (size_t mip = 0; ok && mip < specs.size(); ++mip) {
        ok = (mip == 0 || w->open(tmp, specs[mip], ImageOutput::AppendSubimage)) &&
             write_tiles(*w, specs[mip], (const float *)level.localpixels());
        if (!ok || mip + 1 == specs.size()) break;
        ImageBuf next(ImageSpec(specs[mip + 1].width, specs[mip + 1].height, img->channels, TypeDesc::FLOAT));
        ok = ImageBufAlgo::resize(next, level, "lanczos3");
        level.swap(next);
    }
    std::string why;
    if (!ok || !w->close()) why = w->geterror() + level.geterror();
    else texture_reads_back(tmp, (int)specs.size(), why);
    if (!why.empty()) {
        set_err(err, errlen, path + ": cannot write texture: " + why);
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

soak_status probe_image(const char *path, int *width, int *height, int *channels, char *err, size_t errlen)
{
    auto in = open_named_reader(path, err, errlen);
    if (!in) return SOAK_ERR_IO;
    const ImageSpec &spec = in->spec();
    *width = spec.width;
    *height = spec.height;
    *channels = spec.nchannels < 4 ? spec.nchannels : 4;
    return SOAK_OK;
}

// No worker threads in the library: reads run in a forked child
// (core/src/image_contain.c), which inherits the pools' bookkeeping but not
// their threads, so an EXR read after an EXR write waited forever for
// OpenEXR's workers. Our images are read and written whole, once.
void no_worker_threads()
{
    static std::once_flag once;
    std::call_once(once, [] {
        OIIO::attribute("threads", 1);
        OIIO::attribute("exr_threads", -1);
    });
}

// The table's entries: C++ exceptions (allocation failures) become status codes.
soak_status plugin_read_to(const char *path, long long payload_bytes, const soak_image_sink *sink, char *err,
                           size_t errlen)
{
    no_worker_threads();
    try {
        return read_to_sink(path, payload_bytes, sink, err, errlen);
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path) + ": cannot read image: " + e.what());
        return SOAK_ERR_NOMEM;
    }
}

soak_status plugin_probe(const char *path, int *width, int *height, int *channels, char *err, size_t errlen)
{
    no_worker_threads();
    try {
        return probe_image(path, width, height, channels, err, errlen);
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path) + ": cannot read image: " + e.what());
        return SOAK_ERR_NOMEM;
    }
}

soak_status plugin_encode(const char *path, const char *ext, const soak_image *img, const soak_image_write_opts *opts,
                          unsigned char **bytes, size_t *n_bytes, char *err, size_t errlen)
{
    no_worker_threads();
    try {
        return encode_image(path, ext, img, opts, bytes, n_bytes, err, errlen);
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path) + ": cannot encode image: " + e.what());
        return SOAK_ERR_NOMEM;
    }
}

soak_status plugin_write_tx(const char *tmp, const char *path, const soak_image *img, char *err, size_t errlen)
{
    no_worker_threads();
    try {
        return write_tx(tmp, path, img, err, errlen);
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string(path) + ": cannot write texture: " + e.what());
        return SOAK_ERR_NOMEM;
    }
}

} // namespace

extern "C" __attribute__((visibility("default"))) const soak_image_plugin soak_image_plugin_v3 = {
    plugin_read_to, plugin_probe, plugin_encode, plugin_write_tx};
