#include "render/image_file.h"

#include <chrono>
#include <cstdlib>
#include <future>
#include <mutex>

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/plugin_library.h"
#include "image_writer_abi.h"

namespace gridifs {
namespace {

constexpr const char* kPluginFile = "libgridifs_image_io.so";

using WriteFunction = int (*)(const GridifsImageRequest*, char*, size_t);
using ReadGreyFunction = int (*)(const char*, GridifsGreyReceiver, void*, char*, size_t);

struct ImageWriter {
  WriteFunction write = nullptr;
  ReadGreyFunction readGrey = nullptr;
  std::string problem;  // why it could not be loaded
};

ImageWriter load() {
  const PluginLibrary plugin =
      loadPluginLibrary(kPluginFile, "GRIDIFS_IMAGE_IO", GRIDIFS_IMAGE_IO_BUILD_DIR, "gridifs_image_io_abi_version",
                        GRIDIFS_IMAGE_IO_ABI_VERSION, "the image library");
  if (!plugin.handle) return {nullptr, nullptr, plugin.problem};
  const auto write = reinterpret_cast<WriteFunction>(plugin.symbol("gridifs_image_io_write"));
  const auto readGrey = reinterpret_cast<ReadGreyFunction>(plugin.symbol("gridifs_image_io_read_grey"));
  if (!write || !readGrey)
    return {nullptr, nullptr,
            std::string("the image library (") + kPluginFile + ") is from another version of GridIFS"};
  return {write, readGrey, {}};
}

struct Loading {
  std::once_flag started;
  std::shared_future<ImageWriter> writer;
};

Loading& loading() {
  static Loading state;
  return state;
}

// Starts loading once: on a helper thread when asked ahead of time, else on first use.
const ImageWriter& writer(std::launch how) {
  Loading& state = loading();
  std::call_once(state.started, [&] { state.writer = std::async(how, load).share(); });
  return state.writer.get();
}

thread_local ImageCapture::Receiver* tCapture = nullptr;

int storedCode(StoredSample s) {
  switch (s) {
    case StoredSample::UInt8:
      return GRIDIFS_STORED_UINT8;
    case StoredSample::UInt16:
      return GRIDIFS_STORED_UINT16;
    case StoredSample::Half:
      return GRIDIFS_STORED_HALF;
    case StoredSample::Float:
      return GRIDIFS_STORED_FLOAT;
  }
  return GRIDIFS_STORED_UINT8;
}

void write(const std::filesystem::path& file, const ImageFileLayout& layout, bool isFloat, const void* pixels) {
  if (tCapture) {
    (*tCapture)(file, layout, isFloat, pixels);
    return;
  }
  const ImageWriter& plugin = writer(std::launch::deferred);
  if (!plugin.write) throw IoError("cannot write " + file.string() + ": " + plugin.problem);
  std::vector<const char*> names;
  for (const std::string& name : layout.channels) names.push_back(name.c_str());
  AtomicFile atomic(file);
  const std::string temporary = atomic.temporaryPath().string();
  const GridifsImageRequest request{temporary.c_str(),
                                    layout.width,
                                    layout.height,
                                    int(names.size()),
                                    names.data(),
                                    layout.alphaChannel,
                                    layout.zChannel,
                                    storedCode(layout.stored),
                                    isFloat ? 1 : 0,
                                    pixels,
                                    layout.description.c_str(),
                                    layout.worldToCamera.size() == 16 ? layout.worldToCamera.data() : nullptr,
                                    layout.worldToNDC.size() == 16 ? layout.worldToNDC.data() : nullptr};
  char message[1024] = {};
  if (!plugin.write(&request, message, sizeof message)) throw IoError("cannot write " + file.string() + ": " + message);
  atomic.commit();
}

}  // namespace

ImageCapture::ImageCapture(Receiver receive) : receive_(std::move(receive)), outer_(tCapture) { tCapture = &receive_; }

ImageCapture::~ImageCapture() { tCapture = outer_; }

GreyImage readGreyImage(const std::filesystem::path& file) {
  const ImageWriter& plugin = writer(std::launch::deferred);
  if (!plugin.readGrey) throw IoError("cannot read " + file.string() + ": " + plugin.problem);
  GreyImage image;
  auto receive = [](void* context, int width, int height, const float* grey) {
    auto& out = *static_cast<GreyImage*>(context);
    out.width = width;
    out.height = height;
    out.grey.assign(grey, grey + std::size_t(width) * std::size_t(height));
  };
  char message[1024] = {};
  if (!plugin.readGrey(file.c_str(), receive, &image, message, sizeof message))
    throw IoError("cannot read " + file.string() + ": " + message);
  return image;
}

void startLoadingImageWriter() {
  if (tCapture) return;  // nothing will be written to a file
  Loading& state = loading();
  std::call_once(state.started, [&] { state.writer = std::async(std::launch::async, load).share(); });
}

void loadImageWriterNow() {
  if (tCapture) return;
  writer(std::launch::deferred);
}

bool imageWriterLoaded() {
  const Loading& state = loading();
  return state.writer.valid() && state.writer.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

void writeImageFile(const std::filesystem::path& file, const ImageFileLayout& layout, const std::uint8_t* pixels) {
  write(file, layout, false, pixels);
}

void writeImageFile(const std::filesystem::path& file, const ImageFileLayout& layout, const float* pixels) {
  write(file, layout, true, pixels);
}

}  // namespace gridifs
