#include "ui/shell/theme.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <filesystem>

namespace gridifs::ui {

float applyTheme(float scale) {
  // From ImGui's defaults each time: ScaleAllSizes multiplies whatever the style holds.
  ImGuiStyle& style = ImGui::GetStyle();
  style = ImGuiStyle();
  ImGui::StyleColorsDark();
  style.WindowPadding = ImVec2(10, 8);
  style.FramePadding = ImVec2(7, 4);
  style.ItemSpacing = ImVec2(8, 6);
  style.ItemInnerSpacing = ImVec2(6, 4);
  style.ScrollbarSize = 13;
  style.GrabMinSize = 10;
  style.WindowRounding = 4;
  style.ChildRounding = 3;
  style.FrameRounding = 3;
  style.PopupRounding = 4;
  style.GrabRounding = 3;
  style.TabRounding = 3;
  style.WindowBorderSize = 1;
  style.FrameBorderSize = 0;
  style.WindowTitleAlign = ImVec2(0.0f, 0.5f);

  ImVec4* c = style.Colors;
  const ImVec4 accent(0.30f, 0.56f, 0.86f, 1.0f);
  c[ImGuiCol_Text] = ImVec4(0.90f, 0.91f, 0.93f, 1.0f);
  c[ImGuiCol_TextDisabled] = ImVec4(0.55f, 0.57f, 0.62f, 1.0f);
  c[ImGuiCol_WindowBg] = ImVec4(0.125f, 0.13f, 0.145f, 1.0f);
  c[ImGuiCol_ChildBg] = ImVec4(0.0f, 0.0f, 0.0f, 0.0f);
  c[ImGuiCol_PopupBg] = ImVec4(0.14f, 0.145f, 0.16f, 0.98f);
  c[ImGuiCol_Border] = ImVec4(0.22f, 0.23f, 0.26f, 1.0f);
  c[ImGuiCol_FrameBg] = ImVec4(0.19f, 0.20f, 0.23f, 1.0f);
  c[ImGuiCol_FrameBgHovered] = ImVec4(0.24f, 0.26f, 0.30f, 1.0f);
  c[ImGuiCol_FrameBgActive] = ImVec4(0.27f, 0.30f, 0.36f, 1.0f);
  c[ImGuiCol_TitleBg] = ImVec4(0.10f, 0.105f, 0.12f, 1.0f);
  c[ImGuiCol_TitleBgActive] = ImVec4(0.14f, 0.16f, 0.20f, 1.0f);
  c[ImGuiCol_TitleBgCollapsed] = c[ImGuiCol_TitleBg];
  c[ImGuiCol_MenuBarBg] = ImVec4(0.10f, 0.105f, 0.12f, 1.0f);
  c[ImGuiCol_ScrollbarBg] = ImVec4(0.10f, 0.105f, 0.12f, 0.6f);
  c[ImGuiCol_CheckMark] = accent;
  c[ImGuiCol_SliderGrab] = ImVec4(0.36f, 0.60f, 0.88f, 1.0f);
  c[ImGuiCol_SliderGrabActive] = ImVec4(0.50f, 0.72f, 0.98f, 1.0f);
  c[ImGuiCol_Button] = ImVec4(0.22f, 0.24f, 0.28f, 1.0f);
  c[ImGuiCol_ButtonHovered] = ImVec4(0.28f, 0.38f, 0.52f, 1.0f);
  c[ImGuiCol_ButtonActive] = ImVec4(0.30f, 0.46f, 0.68f, 1.0f);
  c[ImGuiCol_Header] = ImVec4(0.24f, 0.33f, 0.46f, 0.8f);
  c[ImGuiCol_HeaderHovered] = ImVec4(0.28f, 0.40f, 0.56f, 0.9f);
  c[ImGuiCol_HeaderActive] = ImVec4(0.30f, 0.46f, 0.66f, 1.0f);
  c[ImGuiCol_Separator] = c[ImGuiCol_Border];
  c[ImGuiCol_ResizeGrip] = ImVec4(0.30f, 0.56f, 0.86f, 0.20f);
  c[ImGuiCol_ResizeGripHovered] = ImVec4(0.30f, 0.56f, 0.86f, 0.6f);
  c[ImGuiCol_ResizeGripActive] = accent;
  c[ImGuiCol_PlotHistogram] = ImVec4(0.95f, 0.62f, 0.20f, 1.0f);
  c[ImGuiCol_TableRowBgAlt] = ImVec4(1.0f, 1.0f, 1.0f, 0.03f);
  c[ImGuiCol_ModalWindowDimBg] = ImVec4(0.0f, 0.0f, 0.0f, 0.45f);
  style.ScaleAllSizes(scale);

  // DejaVu Sans (Debian's fonts-dejavu-core) reads well at small sizes and has the symbols the
  // panels use (·, °, →, ×); ImGui's built-in bitmap font is the fallback.
  ImGuiIO& io = ImGui::GetIO();
  const float size = 15.0f * scale;
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x205E, 0x2190,
                                   0x21FF, 0x2200, 0x22FF, 0x25A0, 0x25FF, 0};
  for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
                           "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf"}) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) {
      ImFontConfig config;
      config.OversampleH = 2;
      if (io.Fonts->AddFontFromFileTTF(path, size, &config, ranges)) return size;
    }
  }
  ImFontConfig config;
  config.SizePixels = 13.0f * scale;
  io.Fonts->AddFontDefault(&config);
  return config.SizePixels;
}

float rescaleTheme(float scale) {
  ImGui::GetIO().Fonts->Clear();
  const float size = applyTheme(scale);
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
  return size;
}

}  // namespace gridifs::ui
