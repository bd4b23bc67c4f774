// assets/codec/image_codec_abi.h — the C interface of the image codec module (internal).
//
// OpenImageIO brings about 270 shared libraries with it (OpenCV, FFmpeg, GDAL, OpenVDB...)
// whose loading and static initializers cost every start of the game about 0.3 s and 110 MB
// of resident memory, even for `--help` or a refused level. So the one file that includes
// OpenImageIO (oiio_codec.cpp) is built as the module libarcfire_image_codec.so, and
// assets/image_codec.cpp loads it with dlopen on the first image decoded or encoded.
//
// Plain C types only, and no exception crosses it: the module catches everything and answers
// with a message. Messages come back as malloc'ed strings, freed with arc_codec_free().
// The game reaches these functions only through the loaded module's addresses, in
// assets/image_codec.h, whose banner shows a decode (open, then read and close).
#pragma once
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

// Raised whenever a signature below changes: a stale module is refused by the loader.
#define ARC_CODEC_ABI_VERSION 1

// The module exports these whatever the default symbol visibility of the build.
#define ARC_CODEC_EXPORT __attribute__((visibility("default")))

typedef struct ArcCodecReader ArcCodecReader;

int arc_codec_abi_version(void);

// Opens `size` bytes as an image in `format` (a bare extension: "png", "jpg"); `name` is for
// the library's messages. On success the reader holds `data` (which must outlive it) and the
// image's width, height and channel count are set; on failure NULL and *err is the library's
// message.
ArcCodecReader* arc_codec_open(const unsigned char* data, size_t size, const char* format, const char* name,
                               int* width, int* height, int* channels, char** err);
// Decodes the whole image as 8 bits per channel (deeper data converted by the library,
// clamped and rounded), `channels` per pixel, into width*height*channels bytes. 1 on success,
// 0 with the library's message in *err.
int arc_codec_read(ArcCodecReader* reader, int channels, unsigned char* pixels, char** err);
// Frees the reader. After a failure (ok == 0) the library's pending messages are dropped
// first: they are in the caller's message already and would otherwise be printed to stderr.
void arc_codec_close(ArcCodecReader* reader, int ok);

// Encodes RGBA8 (rows top to bottom) in the format of `path`'s extension, in memory.
// 0: *bytes (malloc'ed) and *size are set; 1: no writer for that extension can encode in
// memory; 2: encoding failed, the library's message in *err.
int arc_codec_encode(const char* path, int width, int height, const unsigned char* rgba, unsigned char** bytes,
                     size_t* size, char** err);

// Frees a message or an encoded buffer the module handed out.
void arc_codec_free(void* p);

#ifdef __cplusplus
}
#endif
