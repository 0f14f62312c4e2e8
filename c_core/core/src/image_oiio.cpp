// OpenImageIO shim behind soak/image.h. The only C++ in libsoak.
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

extern "C" {
#include "soak/image.h"
}

using namespace OIIO;

namespace {

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg.c_str());
}

std::string extension_of(const std::string &path)
{
    size_t slash = path.find_last_of('/');
    size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot + 1);
    for (auto &c : ext) c = (char)std::tolower((unsigned char)c);
    return ext;
}

std::string temp_path_for(const std::string &path)
{
    size_t slash = path.find_last_of('/');
    std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    return dir + "." + base + ".tmp" + std::to_string((long)getpid()) + "." + extension_of(path);
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

} // namespace

extern "C" soak_status soak_image_alloc(soak_image *img, int width, int height, int channels)
{
    if (!img) return SOAK_ERR_NULL;
    img->pixels = nullptr;
    if (!(width >= 1 && width <= 65536 && height >= 1 && height <= 65536 && channels >= 1 && channels <= 4))
        return SOAK_ERR_ARG;
    size_t n = (size_t)width * (size_t)height * (size_t)channels;
    img->pixels = (float *)std::calloc(n, sizeof(float));
    if (!img->pixels) return SOAK_ERR_NOMEM;
    img->width = width;
    img->height = height;
    img->channels = channels;
    return SOAK_OK;
}

extern "C" void soak_image_free(soak_image *img)
{
    if (!img) return;
    std::free(img->pixels);
    img->pixels = nullptr;
    img->width = img->height = img->channels = 0;
}

extern "C" soak_status soak_image_read(const char *path, soak_image *img, char *err, size_t errlen)
{
    if (!path || !img) return SOAK_ERR_NULL;
    img->pixels = nullptr;
    auto in = ImageInput::open(path);
    if (!in) {
        set_err(err, errlen, std::string(path) + ": cannot read image: " + OIIO::geterror());
        return SOAK_ERR_IO;
    }
    const ImageSpec &spec = in->spec();
    int ch = spec.nchannels < 4 ? spec.nchannels : 4;
    if (spec.depth > 1) {
        set_err(err, errlen, std::string(path) + ": volume images are not supported");
        return SOAK_ERR_UNSUPPORTED;
    }
    soak_status st = soak_image_alloc(img, spec.width, spec.height, ch);
    if (st != SOAK_OK) {
        set_err(err, errlen, std::string(path) + ": image size out of range or out of memory");
        return st;
    }
    if (!in->read_image(0, 0, 0, ch, TypeDesc::FLOAT, img->pixels)) {
        set_err(err, errlen, std::string(path) + ": truncated or unreadable image data: " + in->geterror());
        soak_image_free(img);
        return SOAK_ERR_IO;
    }
    in->close();
    size_t n = (size_t)img->width * img->height * img->channels;
    for (size_t i = 0; i < n; ++i)
        if (!std::isfinite(img->pixels[i])) img->pixels[i] = 0.0f;
    return SOAK_OK;
}

extern "C" soak_status soak_path_check_writable(const char *path, char *err, size_t errlen)
{
    if (!path || !*path) {
        set_err(err, errlen, "output path is empty");
        return SOAK_ERR_ARG;
    }
    std::string p(path);
    size_t slash = p.find_last_of('/');
    std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : p.substr(0, slash));
    struct stat sb;
    if (stat(dir.c_str(), &sb) != 0 || !S_ISDIR(sb.st_mode)) {
        set_err(err, errlen, p + ": output folder '" + dir + "' does not exist");
        return SOAK_ERR_IO;
    }
    if (access(dir.c_str(), W_OK) != 0) {
        set_err(err, errlen, p + ": output folder '" + dir + "' is not writable");
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

extern "C" int soak_path_same(const char *a, const char *b)
{
    if (!a || !b) return 0;
    if (std::strcmp(a, b) == 0) return 1;
    struct stat sa, sb;
    if (stat(a, &sa) != 0 || stat(b, &sb) != 0) return 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

static soak_status write_buf(const std::string &path, ImageBuf &buf, TypeDesc type, char *err, size_t errlen)
{
    std::string tmp = temp_path_for(path);
    buf.set_write_format(type);
    if (!buf.write(tmp)) {
        std::remove(tmp.c_str());
        set_err(err, errlen, path + ": cannot write image: " + buf.geterror());
        return SOAK_ERR_IO;
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        set_err(err, errlen, path + ": cannot move finished image into place: " + std::strerror(errno));
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}

extern "C" soak_status soak_image_write(const char *path, const soak_image *img, const soak_image_write_opts *opts,
                                        char *err, size_t errlen)
{
    if (!path || !img || !img->pixels) return SOAK_ERR_NULL;
    soak_status st = soak_path_check_writable(path, err, errlen);
    if (st != SOAK_OK) return st;
    std::string ext = extension_of(path);
    if (ext.empty()) {
        set_err(err, errlen, std::string(path) + ": output needs an extension (.exr, .png, .tif, ...)");
        return SOAK_ERR_ARG;
    }
    soak_image_write_opts o = {SOAK_TONE_LINEAR, SOAK_PIXEL_AUTO};
    if (opts) o = *opts;
    TypeDesc type = pixel_type_for(ext, o.pixel_type);
    ImageSpec spec(img->width, img->height, img->channels, TypeDesc::FLOAT);
    if (o.tone == SOAK_TONE_SRGB) spec.attribute("oiio:ColorSpace", "sRGB");
    else spec.attribute("oiio:ColorSpace", "Linear");
    if (ext == "exr") spec.attribute("compression", "zip");
    ImageBuf buf(spec);
    size_t n = (size_t)img->width * img->height * img->channels;
    float *dst = (float *)buf.localpixels();
    bool integer = type.basetype == TypeDesc::UINT16 || type.basetype == TypeDesc::UINT8;
    for (size_t i = 0; i < n; ++i) {
        float v = img->pixels[i];
        if (!std::isfinite(v)) v = 0.0f;
        if (o.tone == SOAK_TONE_SRGB && (img->channels < 4 || (i % 4) != 3)) v = srgb_encode(v);
        if (integer) v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
        dst[i] = v;
    }
    return write_buf(path, buf, type, err, errlen);
}

extern "C" soak_status soak_image_write_tx(const char *path, const soak_image *img, char *err, size_t errlen)
{
    if (!path || !img || !img->pixels) return SOAK_ERR_NULL;
    soak_status st = soak_path_check_writable(path, err, errlen);
    if (st != SOAK_OK) return st;
    ImageSpec spec(img->width, img->height, img->channels, TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", "Linear");
    ImageBuf src(spec, (void *)img->pixels);
    ImageSpec config;
    config.format = TypeDesc::HALF;
    config.attribute("maketx:filtername", "lanczos3");
    std::string tmp = temp_path_for(path);
    if (!ImageBufAlgo::make_texture(ImageBufAlgo::MakeTxTexture, src, tmp, config)) {
        std::remove(tmp.c_str());
        set_err(err, errlen, std::string(path) + ": cannot make texture: " + OIIO::geterror());
        return SOAK_ERR_IO;
    }
    if (std::rename(tmp.c_str(), path) != 0) {
        std::remove(tmp.c_str());
        set_err(err, errlen, std::string(path) + ": cannot move finished texture into place");
        return SOAK_ERR_IO;
    }
    return SOAK_OK;
}
