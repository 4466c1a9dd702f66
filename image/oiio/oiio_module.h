/* The plain C entry point of hexant's OpenImageIO module (libhexant_oiio.so,
   image/oiio/oiio_module.cpp): a versioned table of functions that hexant
   loads with dlopen the first time a file needs OpenImageIO
   (image/oiio_library.hpp). Linked into hexant, OpenImageIO's plugins and
   their libraries would cost every process ~0.35 s and ~120 MB at start
   (docs/benchmarks.md); loaded here, only a run that reads or writes TGA,
   TIFF, Radiance HDR, PPM/PGM or BMP pays it. No C++ type and no exception
   crosses this boundary: each function returns 0 on success, else writes
   its reason (NUL-ended) into `error`. */
#ifndef HEXANT_OIIO_MODULE_H
#define HEXANT_OIIO_MODULE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bumped whenever a field or a function's meaning changes: hexant refuses a
   module of another version (an old one left installed). */
#define HEXANT_OIIO_API_VERSION 1
#define HEXANT_OIIO_ENTRY "hexant_oiio_api"

/* What a file holds, as its header says, and its pixels once read. */
struct HexantOiioImage {
    int width, height;
    int channels;       /* 1 (gray), 2 (gray, alpha), 3 (RGB) or 4 (RGBA) */
    int bits;           /* the file's bits per sample (8, 16, 32 for float) */
    int is_float;       /* 1: the file stores floats (Radiance HDR) */
    int has_palette;    /* 1: the file stores palette indices (expanded here) */
    char format[32];    /* OpenImageIO's name of the format: "targa", "tiff" */
};

/* Allocates `count` floats for the pixels (rows top to bottom, channels
   interleaved) in the caller's memory; null when it cannot. */
typedef float* (*HexantOiioAllocate)(void* context, size_t count);

struct HexantOiioApi {
    int version; /* HEXANT_OIIO_API_VERSION */
    /* OpenImageIO's version, as "2.4.7". */
    const char* (*library_version)(void);
    /* Reads the first image of `path` with the reader of `format`
       (OpenImageIO's name: "targa", "tiff", "hdr", "pnm", "bmp"): its header
       first, refused when width x height is more than `max_pixels` (then
       returns 2, before any pixel is decoded or memory taken for them),
       then its pixels as floats (8- and 16-bit samples scaled to [0, 1],
       alpha not premultiplied) into memory from `allocate`. */
    int (*read)(const char* path, const char* format, size_t max_pixels,
                struct HexantOiioImage* image, HexantOiioAllocate allocate, void* context,
                char* error, size_t error_size);
    /* Writes `width` x `height` RGB pixels (rows top to bottom) in `format`
       to the file open at descriptor `fd` (reopened as /proc/self/fd/N,
       never by its name): bytes when `is_float` is 0, else floats.
       `compression` is OpenImageIO's ("rle" for a run-length Targa) or
       null. */
    int (*write)(int fd, const char* format, const char* compression, int width, int height,
                 int is_float, const void* pixels, char* error, size_t error_size);
};

/* The module's one exported symbol: its table when `version` is the one it
   was built with, else null. */
const struct HexantOiioApi* hexant_oiio_api(int version);

#ifdef __cplusplus
}
#endif

#endif
