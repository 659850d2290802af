#pragma once
// The palette editor: a gradient of keys (position + colour) that becomes the flame display's
// 256-entry palette (Draves & Reckase 2003, §5). It starts from the current palette or any of
// ours and flam3's, edits keys (add, drag, recolour, delete) as one undo step per gesture through
// the Document (render.flame.palette_keys), previews the 256 entries, and saves the gradient as
// NAME.palette.json beside the project, which the project then references as "file:NAME.palette.json".
#include <string>
#include <vector>

#include "model/flame_settings.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

struct PaletteCatalog;

class PaletteEditor {
 public:
  void open() { open_ = true; }
  bool isOpen() const { return open_; }
  /// Draws the window while it is open. `catalog` lists the palettes to start from.
  void draw(ModellerState& state, EditQueue& edits, const PaletteCatalog& catalog);

 private:
  void drawStart(ModellerState& state, EditQueue& edits, const PaletteCatalog& catalog,
                 const std::vector<PaletteKey>& keys);
  void drawGradient(ModellerState& state, EditQueue& edits, const std::vector<PaletteKey>& keys);
  void drawKey(ModellerState& state, EditQueue& edits, const std::vector<PaletteKey>& keys);
  void drawSave(ModellerState& state, EditQueue& edits, const std::vector<PaletteKey>& keys);

  bool open_ = false;
  int selected_ = 0;  // index into the stored keys
  std::string name_ = "gradient";
  std::string message_;
};

}  // namespace gridifs::ui
