/* The seam to OpenImageIO (C++): opaque pointers in, status enums out, every exception caught
 * in image_io_oiio.cpp. All decisions (formats, limits, conversions, error wording, temporary
 * files) are made in C by image_io.c; the adapter only passes them on. Internal to render/.
 */
#ifndef RENDER_IMAGE_IO_OIIO_H
#define RENDER_IMAGE_IO_OIIO_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rd_oiio_status {
    RD_OIIO_OK = 0,
    RD_OIIO_ERR_OPEN, /* no reader could open the file / no writer for the format */
    RD_OIIO_ERR_READ, /* the header was fine, the pixels were not */
    RD_OIIO_ERR_WRITE,
    RD_OIIO_ERR_NOMEM,
    RD_OIIO_ERR_NO_PROXY /* this format's writer cannot write to memory */
} rd_oiio_status;

typedef struct rd_oiio_input rd_oiio_input;

typedef struct rd_oiio_input_info {
    int width, height, depth, channels;
    int is_float; /* the file stores half, float or double */
    int deep;     /* deep (per-pixel sample list) data */
    char format_name[32];
    char colorspace[64]; /* the "oiio:ColorSpace" attribute, "" when absent */

    float x_resolution;       /* the "XResolution" attribute, 0 when absent */
    char resolution_unit[16]; /* "ResolutionUnit": "in", "cm", "none", "" ... */
} rd_oiio_input_info;

/* Opens PATH and reads its header only. unassociated_alpha asks the reader to keep alpha as
 * stored instead of premultiplying it. */
rd_oiio_status rd_oiio_open(const char *path, int unassociated_alpha, rd_oiio_input **out,
                            rd_oiio_input_info *info, char *err, size_t err_size);

/* Reads subimage 0, mip level 0, channels [0, channels) as float into dst, which holds
 * width*height*channels floats. */
rd_oiio_status rd_oiio_read_float(rd_oiio_input *in, int channels, float *dst, char *err,
                                  size_t err_size);

void rd_oiio_close(rd_oiio_input *in);

typedef enum rd_oiio_type { RD_OIIO_UINT8 = 0, RD_OIIO_HALF, RD_OIIO_FLOAT } rd_oiio_type;

typedef struct rd_oiio_write_desc {
    const char *path;   /* where to write (a temporary name; its extension is not used) */
    const char *format; /* OpenImageIO format name: "png", "jpeg", "tiff", "openexr", ... */
    int width, height, channels;
    rd_oiio_type data_type;  /* type of pixels[] in memory: RD_OIIO_UINT8 or RD_OIIO_FLOAT */
    rd_oiio_type file_type;  /* type stored in the file */
    const void *pixels;      /* row-major, top row first, channels interleaved */
    const char *compression; /* "Compression" attribute, NULL for the writer's default */
    const char *colorspace;  /* "oiio:ColorSpace" attribute, NULL for none */
    int unassociated_alpha;  /* write alpha as given, do not un-premultiply */
    float dpi;               /* > 0: XResolution = YResolution = dpi, ResolutionUnit inch */
} rd_oiio_write_desc;

rd_oiio_status rd_oiio_write(const rd_oiio_write_desc *desc, char *err, size_t err_size);

/* The encoded file's bytes (malloc'd; the caller frees data). */
typedef struct rd_oiio_bytes {
    unsigned char *data;
    size_t size;
} rd_oiio_bytes;

/* Encodes the image into memory instead of desc->path (which only names it in messages).
 * RD_OIIO_ERR_NO_PROXY: the format's writer cannot; write to a file with rd_oiio_write. */
rd_oiio_status rd_oiio_write_memory(const rd_oiio_write_desc *desc, rd_oiio_bytes *out, char *err,
                                    size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
