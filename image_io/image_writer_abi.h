#pragma once
// The C interface between GridIFS and its image-writer plugin (libgridifs_image_io.so), which is
// the only code linked to OpenImageIO. Plain C types only: the plugin is loaded with dlopen by
// core/render/image_file.cpp, and a stale plugin from an older build is refused by its version.
#include <stddef.h>

#define GRIDIFS_IMAGE_IO_ABI_VERSION 3

#ifdef __cplusplus
extern "C" {
#endif

enum GridifsStoredSample {
  GRIDIFS_STORED_UINT8 = 0,
  GRIDIFS_STORED_UINT16 = 1,
  GRIDIFS_STORED_HALF = 2,
  GRIDIFS_STORED_FLOAT = 3
};

struct GridifsImageRequest {
  const char* path;  // the file to create; its extension picks the format
  int width, height, channelCount;
  const char* const* channelNames;  // channelCount names ("R", "G", "B", "A", "Z", ...)
  int alphaChannel, zChannel;       // -1: none
  int stored;                       // a GridifsStoredSample
  int pixelsAreFloat;               // pixels hold floats (else bytes), interleaved
  const void* pixels;
  const char* description;  // ImageDescription metadata; "" for none
  /// OpenEXR's standard camera attributes, 16 values each in Imath's row-vector order; NULL for
  /// none. Written to EXR files only.
  const float* worldToCamera;
  const float* worldToNDC;
};

/// The plugin's GRIDIFS_IMAGE_IO_ABI_VERSION.
int gridifs_image_io_abi_version(void);

/// Writes the image. Returns 1 on success; 0 with a message (no trailing newline) in `error`.
int gridifs_image_io_write(const struct GridifsImageRequest* request, char* error, size_t errorSize);

/// Receives a read image's grey levels: width × height values in [0, 1], rows top first.
typedef void (*GridifsGreyReceiver)(void* context, int width, int height, const float* grey);

/// Reads the image at `path` (any format OpenImageIO reads) as grey levels: the luminance
/// (Rec. 709 weights) of its colour channels, composited over white by its alpha channel when it
/// has one. Returns 1 on success; 0 with a message in `error`.
int gridifs_image_io_read_grey(const char* path, GridifsGreyReceiver receive, void* context, char* error,
                               size_t errorSize);

#ifdef __cplusplus
}
#endif
