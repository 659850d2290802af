// gridifs_vdb_xray IN.vdb OUT.png [x|y|z]: the summed density of a `gridifs volume` file along
// one axis as a grey image, the way Sokolov & Gentil show measure attractors (their figures 9–14).
// scripts/figures makes the thumbnails of volume figures with it; it is a docs tool, not a verb.
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <exception>
#include <vector>

#include "figures/figure_checks.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: gridifs_vdb_xray IN.vdb OUT.png [x|y|z]\n");
    return 2;
  }
  try {
    const auto grid = gridifs::figures::readDensity(argv[1]);
    if (!grid) {
      std::fprintf(stderr, "%s has no float grid named density.\n", argv[1]);
      return 2;
    }
    int size = 0;
    const auto img = gridifs::figures::xray(*grid, argc > 3 ? argv[3][0] : 'z', size);
    std::vector<float> rgb;  // grey as RGB, like every other figure's image
    for (float v : img) rgb.insert(rgb.end(), {v, v, v});
    auto out = OIIO::ImageOutput::create(argv[2]);
    if (!out || !out->open(argv[2], OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::UINT8)) ||
        !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !out->close()) {
      std::fprintf(stderr, "cannot write %s.\n", argv[2]);
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[1], e.what());
    return 2;
  }
  return 0;
}
