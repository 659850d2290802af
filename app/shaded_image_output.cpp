#include "app/shaded_image_output.h"

#include "app/cli.h"
#include "app/render_setup.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "render/camera.h"
#include "render/image_file.h"

namespace gridifs::cli {

void writeShadedImage(const ShadedImage& image, const RenderImage& snapshot, const Camera& camera,
                      const std::filesystem::path& out, const std::string& description) {
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  ImageFileLayout layout;
  layout.width = image.width;
  layout.height = image.height;
  layout.description = description;
  try {
    if (lowerExtension(out) == "exr") {
      layout.channels = {"R", "G", "B", "A", "Z", "N.x", "N.y", "N.z", "AO", "shadow", "P.x", "P.y", "P.z"};
      layout.alphaChannel = 3;
      layout.zChannel = 4;
      layout.stored = StoredSample::Float;
      const OrbitCamera orbit(camera, image.width, image.height);
      const ExrCameraMatrices matrices = exrCameraMatrices(orbit);
      layout.worldToCamera = matrices.worldToCamera;
      layout.worldToNDC = matrices.worldToNDC;
      const std::size_t k = layout.channels.size();
      std::vector<float> pixels(n * k);
      for (std::size_t i = 0; i < n; ++i) {
        float* px = &pixels[i * k];
        for (int c = 0; c < 4; ++c) px[c] = image.linear[i * 4 + std::size_t(c)];
        const bool hit = image.rgba[i * 4 + 3] != 0;
        px[4] = hit ? snapshot.depth[i] : kEmptyPixelDepth;
        for (int c = 0; c < 3; ++c) px[5 + c] = image.normals[i * 3 + std::size_t(c)];
        px[8] = image.occlusion[i];
        px[9] = image.shadow[i];
        if (hit) {
          const glm::dvec3 p = pixelWorldPosition(orbit, int(i % std::size_t(image.width)),
                                                  int(i / std::size_t(image.width)), snapshot.depth[i]);
          for (int c = 0; c < 3; ++c) px[10 + c] = float(p[c]);
        } else {
          px[10] = px[11] = px[12] = 0.0f;
        }
      }
      writeImageFile(out, layout, pixels.data());
    } else {
      layout.channels = {"R", "G", "B"};
      std::vector<std::uint8_t> pixels(n * 3);
      for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) pixels[i * 3 + std::size_t(c)] = image.rgba[i * 4 + std::size_t(c)];
      writeImageFile(out, layout, pixels.data());
    }
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
}

}  // namespace gridifs::cli
