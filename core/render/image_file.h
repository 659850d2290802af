#pragma once
// One writer for every image file GridIFS produces (z-buffer, flame and shaded renders, the
// modeller's screenshots): OpenImageIO picks the format from the extension, the file is written
// atomically (a temporary renamed over the target), and a failure names the file. OpenImageIO
// lives in a plugin loaded on first use (image_io/image_writer_abi.h says why).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gridifs {

/// How the channels are stored in the file.
enum class StoredSample { UInt8, UInt16, Half, Float };

struct ImageFileLayout {
  int width = 0, height = 0;
  std::vector<std::string> channels;  // e.g. {"R", "G", "B", "A", "Z"}
  int alphaChannel = -1, zChannel = -1;
  StoredSample stored = StoredSample::UInt8;
  std::string description;  // the ImageDescription metadata; empty for none
  /// OpenEXR's standard "worldToCamera" and "worldToNDC" attributes (16 values each in Imath's
  /// row-vector order, render/camera.h: exrCameraMatrices), written to EXR files; empty: none.
  std::vector<float> worldToCamera, worldToNDC;
};

/// Writes interleaved pixels (width · height · channels values; 8-bit or float, converted to
/// `layout.stored`). Throws IoError("cannot write FILE: …") and leaves an existing file as it was.
void writeImageFile(const std::filesystem::path& file, const ImageFileLayout& layout, const std::uint8_t* pixels);
void writeImageFile(const std::filesystem::path& file, const ImageFileLayout& layout, const float* pixels);

/// While one lives, this thread's writeImageFile calls hand their layout and pixels to `receive`
/// instead of writing a file, and the image library is not loaded for them. The Python module
/// renders through the command line's own code with one, so its arrays hold exactly the pixels
/// `gridifs render` writes. `pixels` are 8-bit when `isFloat` is false, floats otherwise.
class ImageCapture {
 public:
  using Receiver = std::function<void(const std::filesystem::path& file, const ImageFileLayout& layout, bool isFloat,
                                      const void* pixels)>;
  explicit ImageCapture(Receiver receive);
  ~ImageCapture();
  ImageCapture(const ImageCapture&) = delete;
  ImageCapture& operator=(const ImageCapture&) = delete;

 private:
  Receiver receive_;
  Receiver* outer_;  // the capture this one hides, restored when it ends
};

/// A grey image: width × height levels in [0, 1], rows top first.
struct GreyImage {
  int width = 0, height = 0;
  std::vector<float> grey;
};

/// Reads an image file (PNG, JPEG, EXR, … through OpenImageIO) as grey levels: the luminance of
/// its colours, over white where it is transparent. Throws IoError("cannot read FILE: …").
GreyImage readGreyImage(const std::filesystem::path& file);

/// Starts loading the image library on a helper thread, so that a later write does not wait for
/// it (call as soon as it is known that an image will be written). Safe to call more than once.
void startLoadingImageWriter();

/// Whether the loading that startLoadingImageWriter began has finished (false before it began).
/// Call on the thread that called startLoadingImageWriter.
bool imageWriterLoaded();
/// Loads the image writer on this thread, now (a no-op once loaded or while capturing): for a
/// render that may use only its own worker threads.
void loadImageWriterNow();

/// The Z value of pixels without points in EXR files (Blender's convention for "background").
inline constexpr float kEmptyPixelDepth = 1e10f;

}  // namespace gridifs
