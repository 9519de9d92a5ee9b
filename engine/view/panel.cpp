#include "engine/view/panel.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "engine/gl/drawn_lights.h"
#include "engine/gl/shading_mode.h"
#include "engine/gl/texture_slot_names.h"

namespace iblkit {

const std::vector<std::string>& viewerHelpLines() {
  static const std::vector<std::string> lines = {
      "1..9            shading mode: unlit, mirror, sh, irradiance, irradiance-ao-bent, sh-ao, sh-ao-bent, prt, full",
      "[ ]             exposure -/+ 0.5 stop (locks it)",
      "A               automatic exposure on / off (off: locked)",
      "drop a file     open a scene (.json), a model (.gltf, .glb) or a map (.exr, .hdr)",
      "left drag       orbit (arrow keys too)",
      "right/mid drag  pan (shift + arrow keys too)",
      "wheel           zoom (+ / - and PageUp / PageDown too)",
      "R               reset the camera to the scene's",
      ", .             previous / next environment map of --env-dir",
      "C               reference view: live, split, difference, image (with --reference)",
      "{ }             previous / next image of a report case (with --reference REPORT --case CASE)",
      "drag divider    move the split (with --reference)",
      "P               screenshot (EXR of the frame + PNG of the view)",
      "Tab             hide / show the panel",
      "H               this help",
      "Esc             quit",
  };
  return lines;
}

float panelScale(float contentScale, int windowWidth, int framebufferWidth) {
  if (!(contentScale > 0.0f) || windowWidth <= 0 || framebufferWidth <= 0) return 1.0f;
  return std::max(1.0f, contentScale * float(windowWidth) / float(framebufferWidth));
}

Panel::Panel(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  window_ = window;
  applyScale();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

void Panel::applyScale() {
  // High-DPI (panel.h, panelScale): where the framebuffer has as many pixels as the window
  // (X11, Windows), ImGui's window coordinates are pixels and the panel is scaled up by the
  // monitor's content scale; where it has more (macOS, Wayland), the backend's framebuffer
  // scale already draws the panel at its size in points.
  float contentX = 1.0f, contentY = 1.0f;
  glfwGetWindowContentScale(window_, &contentX, &contentY);
  int windowWidth = 0, windowHeight = 0, framebufferWidth = 0, framebufferHeight = 0;
  glfwGetWindowSize(window_, &windowWidth, &windowHeight);
  glfwGetFramebufferSize(window_, &framebufferWidth, &framebufferHeight);
  if (windowWidth <= 0 || framebufferWidth <= 0) return;  // minimised: keep the scale
  const float scale = panelScale(contentX, windowWidth, framebufferWidth);
  if (std::abs(scale - scale_) < 1e-3f) return;
  ImGuiStyle style;  // the unscaled sizes, scaled afresh (ScaleAllSizes multiplies what is there)
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  ImGui::GetIO().FontGlobalScale = scale;
  scale_ = scale;
  std::fprintf(stderr, "iblkit-view: panel scaled %gx (content scale %g, window %d px wide, framebuffer %d)\n",
               double(scale), double(contentX), windowWidth, framebufferWidth);
}

Panel::~Panel() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

bool Panel::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool Panel::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

namespace {

void environmentSection(EnvironmentSwitcher& environments) {
  ImGui::Text("environments: %s", environments.folder().string().c_str());
  const std::vector<std::filesystem::path>& files = environments.files();
  const int shown = environments.current();
  const std::string preview = shown < 0 ? "(the bake's)" : files[std::size_t(shown)].filename().string();
  if (ImGui::BeginCombo("map", preview.c_str())) {
    for (int i = 0; i < int(files.size()); ++i)
      if (ImGui::Selectable(files[std::size_t(i)].filename().string().c_str(), i == shown))
        environments.request(i);
    ImGui::EndCombo();
  }
  ImGui::TextWrapped("%s", environments.status().c_str());
}

void materialSection(Renderer& renderer, const std::vector<Material>& originals, int& selected) {
  const std::vector<Material>& materials = renderer.materials();
  if (materials.empty()) return;
  selected = std::clamp(selected, 0, int(materials.size()) - 1);
  auto label = [&](int i) {
    const std::string& name = materials[std::size_t(i)].name;
    return std::to_string(i) + (name.empty() ? "" : ": " + name);
  };
  if (ImGui::BeginCombo("material", label(selected).c_str())) {
    for (int i = 0; i < int(materials.size()); ++i)
      if (ImGui::Selectable(label(i).c_str(), i == selected)) selected = i;
    ImGui::EndCombo();
  }
  Material material = materials[std::size_t(selected)];
  bool changed = ImGui::ColorEdit3("base colour", &material.baseColor.x, ImGuiColorEditFlags_Float);
  changed |= ImGui::SliderFloat("roughness", &material.roughness, 0.0f, 1.0f);
  changed |= ImGui::SliderFloat("metallic", &material.metallic, 0.0f, 1.0f);
  if (ImGui::Button("restore material")) {
    material = originals[std::size_t(selected)];
    changed = true;
  }
  if (changed) renderer.setMaterial(selected, material);
}

// One checkbox per texture slot (FrameSettings::textureSlots): a slot switched off shows what the
// material is without it (its factor alone), to see what the texture contributes.
void textureSection(FrameSettings& settings, const Renderer& renderer) {
  const Scene& scene = renderer.scene();
  ImGui::Text("%zu textures, %zu images, anisotropy %.0f", scene.textures.size(), scene.images.size(),
              renderer.textureAnisotropy());
  for (const EnumName<TextureSlot>& slot : kTextureSlotNames) {
    bool on = (settings.textureSlots & slot.value) != 0;
    if (ImGui::Checkbox(std::string(slot.name).c_str(), &on))
      settings.textureSlots = on ? settings.textureSlots | slot.value : settings.textureSlots & ~unsigned(slot.value);
  }
  if (ImGui::Button("all")) settings.textureSlots = kAllTextureSlots;
  ImGui::SameLine();
  if (ImGui::Button("none")) settings.textureSlots = 0;
}

// The environment's suns (drawn_lights.h): direction, size, brightness and share of the map's
// energy; K, the number drawn as lights in the lights modes, and their shadows.
void lightsSection(FrameSettings& settings, const Renderer& renderer) {
  const std::vector<EnvironmentLight>& suns = renderer.lightStages().lights.suns;
  if (suns.empty()) {
    ImGui::TextWrapped("no suns in this environment: the lights modes draw the map's SH9 and specular chain");
    return;
  }
  if (ImGui::BeginTable("suns", 5, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    for (const char* column : {"#", "azimuth, elevation", "radius", "irradiance lum", "energy"})
      ImGui::TableSetupColumn(column);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < suns.size(); ++i) {
      const EnvironmentLight& sun = suns[i];
      const glm::vec2 angles = lightAzimuthElevation(sun.direction);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%zu", i + 1);
      ImGui::TableNextColumn();
      ImGui::Text("%.1f, %.1f deg", angles.x, angles.y);
      ImGui::TableNextColumn();
      ImGui::Text("%.2f deg", glm::degrees(sun.angularRadius));
      ImGui::TableNextColumn();
      ImGui::Text("%.4g", luminance(sun.irradiance));
      ImGui::TableNextColumn();
      ImGui::Text("%.1f%%", 100.0f * lightEnergyShare(sun, renderer.lightStages().sh9));
    }
    ImGui::EndTable();
  }
  const int available = drawnLightCount(renderer.lightStages(), -1);
  int k = drawnLightCount(renderer.lightStages(), settings.lightCount);
  if (ImGui::SliderInt("lights K", &k, 0, available)) settings.lightCount = k;
  ImGui::Checkbox("shadows", &settings.shadows);
  ImGui::SameLine();
  ImGui::Checkbox("screen-space mask", &settings.shadowMask);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("single-sample frames: the shadows computed once per pixel before the lit pass");
  bool halfMask = settings.shadowMaskDivisor == 2;
  ImGui::SameLine();
  if (ImGui::Checkbox("half-res", &halfMask)) settings.shadowMaskDivisor = halfMask ? 2 : 1;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the mask at half resolution, upsampled with its depths (a quarter of the shadow lookups)");
  if (settings.mode != ShadingMode::Lights && settings.mode != ShadingMode::LightsShadowed)
    ImGui::TextDisabled("(used by the lights and lights-shadowed modes)");
}

void comparisonSection(ReferenceComparison& comparison, bool cameraMoved) {
  ImGui::TextWrapped("reference: %s (%dx%d)", comparison.source().c_str(), comparison.width(), comparison.height());
  int view = int(comparison.view);
  for (const EnumName<ComparisonView>& v : kComparisonViewNames) {
    if (v.value != ComparisonView::Live) ImGui::SameLine();
    ImGui::RadioButton(std::string(v.name).c_str(), &view, int(v.value));
  }
  comparison.view = ComparisonView(view);
  // A report case: its reference and each mode's frame, one shown at a time ({ and } flip).
  if (comparison.count() > 1) {
    if (ImGui::BeginCombo("image", comparison.shownLabel().c_str())) {
      for (int i = 0; i < comparison.count(); ++i)
        if (ImGui::Selectable(comparison.name(i).c_str(), i == comparison.shown())) comparison.show(i);
      ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::TextDisabled("{ }");
  }
  ImGui::Text("showing %s", comparison.shownLabel().c_str());
  if (!comparison.detail(comparison.shown()).empty())
    ImGui::TextWrapped("%s", comparison.detail(comparison.shown()).c_str());
  if (comparison.view == ComparisonView::Split)
    ImGui::SliderFloat("divider", &comparison.divider, 0.0f, 1.0f);
  if (comparison.view == ComparisonView::Difference) {
    ImGui::SliderFloat("max", &comparison.heatMapMax, 0.01f, 10.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    ImGui::TextUnformatted("relMSE per pixel (docs/scoring.md), magma from 0 to max");
  }
  if (cameraMoved) ImGui::TextColored(ImVec4(1, 0.6f, 0.2f, 1), "camera moved: R to compare again");
}

}  // namespace

PanelActions Panel::build(PanelContext& context) {
  applyScale();  // between frames: a window moved to a screen of another scale
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  PanelActions actions;
  if (visible) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("iblkit-view", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushItemWidth(ImGui::GetFontSize() * 12.0f);
    ImGui::Text("%.2f ms/frame (%.1f fps), %dx%d", context.frameMs,
                context.frameMs > 0.0 ? 1000.0 / context.frameMs : 0.0, context.width, context.height);
    ImGui::SameLine();
    ImGui::TextDisabled("(GL)");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", context.contextDescription.c_str());
    FrameSettings& settings = context.settings;
    int mode = 0;
    for (int i = 0; i < int(std::size(kShadingModes)); ++i)
      if (kShadingModes[i] == settings.mode) mode = i;
    if (ImGui::BeginCombo("mode", std::string(shadingModeName(settings.mode)).c_str())) {
      for (int i = 0; i < int(std::size(kShadingModes)); ++i)
        if (ImGui::Selectable(std::string(shadingModeName(kShadingModes[i])).c_str(), i == mode))
          settings.mode = kShadingModes[i];
      ImGui::EndCombo();
    }
    // Moving the slider locks the exposure where it is put; "auto" follows the frame's key again.
    if (ImGui::SliderFloat("exposure", &settings.exposure, -16.0f, 16.0f, "%.1f stops")) context.autoExposure = false;
    ImGui::SameLine();
    ImGui::Checkbox("auto", &context.autoExposure);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("key value from the log-average luminance; unchecked: locked");
    ImGui::SliderFloat("env rotation", &settings.envRotationDegrees, -180.0f, 180.0f, "%.0f deg");
    ImGui::Checkbox("sky", &settings.drawSky);
    ImGui::InputText("##open", openPath_, sizeof openPath_);
    ImGui::SameLine();
    if (ImGui::Button("open") && openPath_[0]) actions.open = openPath_;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("a scene (.json), a model (.gltf, .glb) or a map (.exr, .hdr); or drop one onto the window");
    if (!context.openStatus.empty()) ImGui::TextWrapped("%s", context.openStatus.c_str());
    if (ImGui::CollapsingHeader("environment", ImGuiTreeNodeFlags_DefaultOpen))
      environmentSection(context.environments);
    if (ImGui::CollapsingHeader("textures", context.renderer.scene().textures.empty() ? 0 : ImGuiTreeNodeFlags_DefaultOpen))
      textureSection(settings, context.renderer);
    if (ImGui::CollapsingHeader("lights", ImGuiTreeNodeFlags_DefaultOpen)) lightsSection(settings, context.renderer);
    if (ImGui::CollapsingHeader("material"))
      materialSection(context.renderer, context.originalMaterials, selectedMaterial_);
    if (context.comparison && ImGui::CollapsingHeader("reference", ImGuiTreeNodeFlags_DefaultOpen))
      comparisonSection(*context.comparison, context.cameraMoved);
    actions.resetCamera = ImGui::Button("reset camera (R)");
    ImGui::SameLine();
    actions.screenshot = ImGui::Button("screenshot (P)");
    ImGui::SameLine();
    if (ImGui::Button("help (H)")) showHelp = !showHelp;
    if (!context.lastScreenshot.empty()) ImGui::TextWrapped("%s", context.lastScreenshot.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
  }
  if (showHelp) {
    ImGui::Begin("keys", &showHelp, ImGuiWindowFlags_AlwaysAutoResize);
    for (const std::string& line : viewerHelpLines()) ImGui::TextUnformatted(line.c_str());
    ImGui::End();
  }
  ImGui::Render();
  return actions;
}

void Panel::render() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }

}  // namespace iblkit
