// Thin adapter over OpenImageIO (ARCHITECTURE.md: the C/C++ seam). It turns C arguments into
// OIIO calls and OIIO outcomes into status codes and message text; every exception stops here.
// Decisions about formats, limits and conversions belong to image_io.c, not to this file.
#include "image_io_oiio.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace
{

void set_message(char *err, size_t err_size, const std::string &msg)
{
    if (err != nullptr && err_size > 0) {
        std::snprintf(err, err_size, "%s", msg.empty() ? "unknown OpenImageIO error" : msg.c_str());
    }
}

OIIO::TypeDesc to_typedesc(rd_oiio_type t)
{
    switch (t) {
    case RD_OIIO_HALF:
        return OIIO::TypeDesc::HALF;
    case RD_OIIO_FLOAT:
        return OIIO::TypeDesc::FLOAT;
    case RD_OIIO_UINT8:
    default:
        return OIIO::TypeDesc::UINT8;
    }
}

} // namespace

struct rd_oiio_input {
    std::unique_ptr<OIIO::ImageInput> in;
};

extern "C" rd_oiio_status rd_oiio_open(const char *path, int unassociated_alpha,
                                       rd_oiio_input **out, rd_oiio_input_info *info, char *err,
                                       size_t err_size)
{
    *out = nullptr;
    try {
        OIIO::ImageSpec config;
        if (unassociated_alpha) {
            config.attribute("oiio:UnassociatedAlpha", 1);
        }
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
        if (!in) {
            set_message(err, err_size, OIIO::geterror());
            return RD_OIIO_ERR_OPEN;
        }
        const OIIO::ImageSpec &spec = in->spec();
        *info = rd_oiio_input_info{};
        info->width = spec.width;
        info->height = spec.height;
        info->depth = spec.depth;
        info->channels = spec.nchannels;
        info->is_float = spec.format.is_floating_point() ? 1 : 0;
        info->deep = spec.deep ? 1 : 0;
        std::snprintf(info->format_name, sizeof info->format_name, "%s", in->format_name());
        std::string cs = spec.get_string_attribute("oiio:ColorSpace");
        std::snprintf(info->colorspace, sizeof info->colorspace, "%s", cs.c_str());
        info->x_resolution = spec.get_float_attribute("XResolution", 0.0f);
        std::string unit = spec.get_string_attribute("ResolutionUnit");
        std::snprintf(info->resolution_unit, sizeof info->resolution_unit, "%s", unit.c_str());
        *out = new rd_oiio_input{std::move(in)};
        return RD_OIIO_OK;
    } catch (const std::bad_alloc &) {
        set_message(err, err_size, "out of memory");
        return RD_OIIO_ERR_NOMEM;
    } catch (const std::exception &e) {
        set_message(err, err_size, e.what());
        return RD_OIIO_ERR_OPEN;
    } catch (...) {
        set_message(err, err_size, "unknown exception in OpenImageIO");
        return RD_OIIO_ERR_OPEN;
    }
}

extern "C" rd_oiio_status rd_oiio_read_float(rd_oiio_input *in, int channels, float *dst, char *err,
                                             size_t err_size)
{
    try {
        if (!in->in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, dst)) {
            set_message(err, err_size, in->in->geterror());
            return RD_OIIO_ERR_READ;
        }
        return RD_OIIO_OK;
    } catch (const std::bad_alloc &) {
        set_message(err, err_size, "out of memory");
        return RD_OIIO_ERR_NOMEM;
    } catch (const std::exception &e) {
        set_message(err, err_size, e.what());
        return RD_OIIO_ERR_READ;
    } catch (...) {
        set_message(err, err_size, "unknown exception in OpenImageIO");
        return RD_OIIO_ERR_READ;
    }
}

extern "C" void rd_oiio_close(rd_oiio_input *in)
{
    try {
        if (in != nullptr) {
            if (in->in) {
                in->in->close();
                (void)in->in->geterror(); // drop pending errors so OIIO does not print them
            }
            delete in;
        }
    } catch (...) {
        // Nothing to report on close; the pixels were already read or refused.
    }
}

// Writes through OIIO to d->path, or into *memory when memory is not NULL and the format's
// writer takes an IOProxy. In memory no write can fail, so libjpeg's and libpng's own I/O error
// handling (libjpeg's default error_exit ends the process) is never reached; the caller writes
// the bytes and checks every result itself.
static rd_oiio_status write_image(const rd_oiio_write_desc *d, rd_oiio_bytes *memory, char *err,
                                  size_t err_size)
{
    try {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(d->format);
        if (!out) {
            set_message(err, err_size, OIIO::geterror());
            return RD_OIIO_ERR_OPEN;
        }
        if (memory != nullptr && !out->supports("ioproxy"))
            return RD_OIIO_ERR_NO_PROXY;
        OIIO::Filesystem::IOVecOutput vec;
        if (memory != nullptr && !out->set_ioproxy(&vec)) {
            (void)out->geterror();
            return RD_OIIO_ERR_NO_PROXY;
        }
        OIIO::ImageSpec spec(d->width, d->height, d->channels, to_typedesc(d->file_type));
        if (d->compression != nullptr) {
            spec.attribute("Compression", d->compression);
            // OpenImageIO 2.4's PNG writer reads its zlib level from its own attribute only.
            if (!std::strcmp(d->format, "png") && !std::strncmp(d->compression, "zip:", 4))
                spec.attribute("png:compressionLevel", std::atoi(d->compression + 4));
        }
        if (d->colorspace != nullptr) {
            spec.attribute("oiio:ColorSpace", d->colorspace);
        }
        if (d->unassociated_alpha) {
            spec.attribute("oiio:UnassociatedAlpha", 1);
        }
        if (d->dpi > 0.0f) {
            // PNG pHYs, the JFIF density and the TIFF resolution tags all come from these.
            spec.attribute("XResolution", d->dpi);
            spec.attribute("YResolution", d->dpi);
            spec.attribute("ResolutionUnit", "in"); // "inch" reads back as "none" from JPEG
        }
        if (!out->open(d->path, spec)) {
            set_message(err, err_size, out->geterror());
            return RD_OIIO_ERR_WRITE;
        }
        bool ok = out->write_image(to_typedesc(d->data_type), d->pixels);
        ok = out->close() && ok;
        if (!ok) {
            set_message(err, err_size, out->geterror());
            return RD_OIIO_ERR_WRITE;
        }
        if (memory != nullptr) {
            const std::vector<unsigned char> &bytes = vec.buffer();
            memory->data = static_cast<unsigned char *>(std::malloc(bytes.size() + 1));
            if (memory->data == nullptr) {
                set_message(err, err_size, "out of memory");
                return RD_OIIO_ERR_NOMEM;
            }
            std::memcpy(memory->data, bytes.data(), bytes.size());
            memory->size = bytes.size();
        }
        return RD_OIIO_OK;
    } catch (const std::bad_alloc &) {
        set_message(err, err_size, "out of memory");
        return RD_OIIO_ERR_NOMEM;
    } catch (const std::exception &e) {
        set_message(err, err_size, e.what());
        return RD_OIIO_ERR_WRITE;
    } catch (...) {
        set_message(err, err_size, "unknown exception in OpenImageIO");
        return RD_OIIO_ERR_WRITE;
    }
}

extern "C" rd_oiio_status rd_oiio_write(const rd_oiio_write_desc *d, char *err, size_t err_size)
{
    return write_image(d, nullptr, err, err_size);
}

extern "C" rd_oiio_status rd_oiio_write_memory(const rd_oiio_write_desc *d, rd_oiio_bytes *out,
                                               char *err, size_t err_size)
{
    out->data = nullptr;
    out->size = 0;
    return write_image(d, out, err, err_size);
}
