#include "engine/view/viewer.h"

#include <GLFW/glfw3.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <future>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <memory>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "bakefile/bake_folder.h"
#include "core/auto_exposure.h"
#include "core/error.h"
#include "core/usage_error.h"
#include "engine/gl/gl_debug.h"
#include "engine/gl/render_target.h"
#include "engine/gl/renderer.h"
#include "engine/view/environment_switcher.h"
#include "engine/view/orbit_camera.h"
#include "engine/view/panel.h"
#include "engine/view/reference_comparison.h"
#include "engine/view/screenshot.h"
#include "engine/view/window_context.h"
#include "engine/view/window_input.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

enum class Drag { None, Orbit, Pan, Divider };

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options)
      : options_(options), bake_(options.loadScene(options.input, nullptr, nullptr)), autoExposure_(options.autoExposure) {
    settings_.mode = parseShadingMode(options.mode);
    settings_.exposure = options.exposure;
    settings_.envRotationDegrees = envRotationFromBake(bake_.env, options.envRotation);
    settings_.drawSky = !options.noSky;
    settings_.textureSlots = options.textureSlots;
    settings_.lightCount = options.lightCount;
    settings_.shadows = options.shadows;
    settings_.shadowMask = options.shadowMask;
    settings_.shadowMaskDivisor = options.shadowMaskDivisor;
    settings_.groundVisibility = options.groundVisibility;
    // The reference decides the size (same camera, same pixels) unless --width/--height do.
    int width = bake_.scene.width, height = bake_.scene.height;
    if (!options.references.empty()) {
      width = options.references.front().image.width();
      height = options.references.front().image.height();
    }
    if (options.width > 0) width = options.width;
    if (options.height > 0) height = options.height;

    title_ = "iblkit-view: " + options.input.filename().string();
    window_.emplace(WindowContext::open(width, height, title_, false));
    enableGlDebugOutput(GlDebugMode::Strict);
    renderer_ = std::make_unique<Renderer>(bake_, options.anisotropy);
    originalMaterials_ = renderer_->materials();
    camera_.emplace(sceneCamera(bake_.scene, float(width) / float(height)), bake_.scene.bounds);
    if (!options.references.empty()) {
      comparison_ = std::make_unique<ReferenceComparison>(options.references, options.referenceSource);
      comparison_->view = parseComparisonView(options.compare);
      if (!options.show.empty()) comparison_->show(comparison_->find(options.show));
    }
    environments_ =
        std::make_unique<EnvironmentSwitcher>(options.envDir, bake_.env.rotationDegrees, bake_.env.intensity,
                                              options.prepareEnvironment);
    if (!options.environment.empty()) environments_->requestFile(options.environment);

    GLFWwindow* window = window_->window();
    input_.install(window);  // before the panel's callbacks, which chain to these
    glfwGetCursorPos(window, &cursorX_, &cursorY_);
    glfwGetFramebufferSize(window, &framebufferWidth_, &framebufferHeight_);
    panel_ = std::make_unique<Panel>(window);
    panel_->visible = options.panel;
    checkGlErrors("viewer setup");
  }

  int run() {
    std::vector<double> intervals;
    Clock::time_point previous = Clock::now();
    for (int frame = 0; !window_->shouldClose() && (options_.frames == 0 || frame < options_.frames);
         ++frame) {
      glfwPollEvents();
      if (frame == 1) {  // --open: after the first frame, as if dropped
        std::vector<const char*> paths;
        for (const fs::path& file : options_.open) paths.push_back(file.c_str());
        input_.filesDropped(int(paths.size()), paths.data());
      }
      handleInput();
      pollOpenedScene(false);
      if (std::optional<EnvironmentStages> stages = environments_->poll()) useEnvironment(std::move(*stages));
      updateTitle();
      // The framebuffer's size in pixels, as the last resize event gave it: the GL side (the
      // offscreen targets, the viewport, the projection's aspect) follows it; the cursor and the
      // panel work in window coordinates, which differ on a high-DPI screen.
      const int width = framebufferWidth_, height = framebufferHeight_;
      if (width <= 0 || height <= 0) {  // minimised
        glfwWaitEventsTimeout(0.1);
        continue;
      }
      const std::optional<ScreenshotFiles> capture =
          screenshotRequested_ ? std::optional(timestampedScreenshotFiles(fs::current_path())) : std::nullopt;
      screenshotRequested_ = false;
      drawFrame(width, height, capture, true);
      window_->swapBuffers();
      checkGlErrors("frame");
      const Clock::time_point now = Clock::now();
      const double interval = std::chrono::duration<double, std::milli>(now - previous).count();
      previous = now;
      if (options_.frames > 0) intervals.push_back(interval);  // for the median printed at the end
      recent_.push_back(interval);
      if (recent_.size() > 60) recent_.erase(recent_.begin());
    }
    if (!options_.screenshot.empty()) {
      // A switch still being prefiltered is waited for, so that a scripted run sees it.
      pollOpenedScene(true);
      if (std::optional<EnvironmentStages> stages = environments_->waitForResult())
        useEnvironment(std::move(*stages));
      drawFrame(framebufferWidth_, framebufferHeight_, screenshotFiles(options_.screenshot), false);
      checkGlErrors("screenshot");
    }
    if (options_.frames > 0) {
      // The first two frames compile shader variants and upload: left out of the median when
      // there are more.
      const std::vector<double> steady(intervals.begin() + (intervals.size() > 2 ? 2 : 0), intervals.end());
      std::cout << "iblkit-view: " << intervals.size() << " frames, " << framebufferWidth_ << "x"
                << framebufferHeight_ << ", " << window_->description() << ", median frame time "
                << std::fixed << std::setprecision(2) << median(steady) << " ms, exposure " << settings_.exposure
                << (autoExposure_ ? " (auto)" : " (locked)") << '\n';
    }
    return 0;
  }

 private:
  // Renders the scene, presents it (or the comparison) into the window's back buffer, writes a
  // screenshot if asked (before the panel is drawn, so the panel is not in it) and draws the panel
  // (not for the final --screenshot frame, whose write errors end the run).
  void drawFrame(int width, int height, const std::optional<ScreenshotFiles>& capture, bool withPanel) {
    if (!target_ || target_->width() != width || target_->height() != height)
      target_ = std::make_unique<RenderTarget>(width, height, options_.samples);
    const Camera camera = camera_->camera();
    renderer_->render(camera, settings_, target_->framebuffer(), width, height);
    target_->resolve();
    // Automatic exposure: the frame's key brought to middle grey, measured on the first frame and
    // every kExposureInterval-th after (a read-back of the linear frame; the exposure applies from
    // this frame on, so the first frame shown is already exposed).
    if (autoExposure_ && (exposureAge_ == 0 || exposureAge_ >= kExposureInterval || capture || !withPanel)) {
      settings_.exposure = keyExposure(target_->readColor());
      exposureAge_ = 0;
    }
    ++exposureAge_;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (comparison_)
      comparison_->present(*renderer_, target_->colorTexture(), settings_, width, height);
    else
      renderer_->presentToneMapped(target_->colorTexture(), settings_, 0, 0, width, height);
    if (capture) {
      const Image displayed = readDisplayedPixels(0, 0, width, height);
      const Image radiance = target_->readColor();
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      try {
        writeScreenshot(*capture, radiance, displayed);
        lastScreenshot_ = "saved " + capture->png.string();
        // Flushed: a script driving the window waits for this line.
        std::cout << "iblkit-view: wrote " << capture->exr.string() << " and " << capture->png.string()
                  << std::endl;
      } catch (const Error& e) {
        if (!withPanel) throw;  // --screenshot at exit: the run fails
        lastScreenshot_ = std::string("screenshot failed: ") + e.what();  // P: the panel says why
      }
    }
    if (!withPanel) return;
    PanelContext context{
        settings_, *renderer_, originalMaterials_,     *environments_, comparison_.get(), median(recent_),
        width,     height,     window_->description(), cameraMoved_,   lastScreenshot_, autoExposure_, openStatus_};
    const PanelActions actions = panel_->build(context);
    panel_->render();
    if (actions.resetCamera) resetCamera();
    screenshotRequested_ |= actions.screenshot;
    if (!actions.open.empty()) open(actions.open);
  }

  // The environment a switch prefiltered: uploaded, and kept as the one a model opened later is
  // lit by.
  void useEnvironment(EnvironmentStages stages) {
    renderer_->setEnvironment(stages);
    bake_.env = std::move(stages);
    exposureAge_ = 0;
  }

  // A dropped file, or one the panel's field names: a map is switched to (environment_switcher.h,
  // its errors in the panel); a scene, model or bake folder is loaded (baked in memory when it is
  // not a bake folder) on a worker thread while the window keeps drawing the current one. A file
  // that cannot be opened leaves the scene as it is and says why in the panel.
  void open(const fs::path& file) {
    switch (openedKind(file)) {
      case OpenedKind::Environment:
        environments_->requestFile(file);
        openStatus_.clear();
        report("switching to " + file.string());
        return;
      case OpenedKind::Unsupported:
        openStatus_ = file.string() + ": cannot open (expected .json, .gltf, .glb, .exr, .hdr or a bake folder)";
        report(openStatus_);
        return;
      case OpenedKind::Scene:
        break;
    }
    if (opening_.valid()) {
      openStatus_ = file.string() + ": still opening " + openingFile_.filename().string() + ", try again after it";
      report(openStatus_);
      return;
    }
    openingFile_ = file;
    openingStart_ = Clock::now();
    openingProgress_ = std::make_shared<LoadProgress>();
    opening_ = std::async(std::launch::async,
                          [loader = options_.loadScene, file, current = bake_.env, progress = openingProgress_]() {
                            return loader(file, &current, progress.get());
                          });
    updateOpenStatus();
    report("opening " + file.string());
  }

  void updateOpenStatus() {
    const double seconds = std::chrono::duration<double>(Clock::now() - openingStart_).count();
    openStatus_ = openingProgress_->describe(openingFile_, seconds);
  }

  // Takes the scene a worker has loaded (`wait`: waits for it) and puts it in place of the shown
  // one: renderer, materials, camera (the new scene's), environment switcher.
  void pollOpenedScene(bool wait) {
    if (!opening_.valid()) return;
    if (!wait && opening_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      updateOpenStatus();
      return;
    }
    try {
      BakedScene bake = opening_.get();
      environments_.reset();  // waits for its worker
      renderer_.reset();
      bake_ = std::move(bake);
      renderer_ = std::make_unique<Renderer>(bake_, options_.anisotropy);
      originalMaterials_ = renderer_->materials();
      const float aspect = float(std::max(framebufferWidth_, 1)) / float(std::max(framebufferHeight_, 1));
      camera_.emplace(sceneCamera(bake_.scene, aspect), bake_.scene.bounds);
      cameraMoved_ = false;
      settings_.envRotationDegrees = 0.0f;
      environments_ = std::make_unique<EnvironmentSwitcher>(options_.envDir, bake_.env.rotationDegrees,
                                                            bake_.env.intensity, options_.prepareEnvironment);
      title_ = "iblkit-view: " + openingFile_.filename().string();
      openStatus_ = "opened " + openingFile_.string();
      exposureAge_ = 0;
      checkGlErrors("open");
    } catch (const Error& e) {
      openStatus_ = std::string("cannot open: ") + e.what();
    } catch (const std::exception& e) {
      openStatus_ = "cannot open " + openingFile_.string() + ": " + e.what();
    }
    report(openStatus_);
  }

  // What the panel says about opening files, also on stderr (scripts and tests read it).
  static void report(const std::string& line) { std::cerr << "iblkit-view: " << line << '\n'; }

  void resetCamera() {
    camera_->reset();
    cameraMoved_ = false;
  }

  void handleKey(int key, int mods) {
    // Keys 1 to 9 choose the first nine modes (the panel's menu has them all).
    if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9 && key - GLFW_KEY_1 < int(std::size(kShadingModes)))
      settings_.mode = kShadingModes[key - GLFW_KEY_1];
    switch (key) {
      case GLFW_KEY_ESCAPE:
        glfwSetWindowShouldClose(window_->window(), GLFW_TRUE);
        break;
      case GLFW_KEY_LEFT_BRACKET:
      case GLFW_KEY_RIGHT_BRACKET: {
        const int direction = key == GLFW_KEY_RIGHT_BRACKET ? 1 : -1;
        if (mods & GLFW_MOD_SHIFT) {  // { and }: flip through the images of --reference
          flipImage(direction);
        } else {
          settings_.exposure += 0.5f * float(direction);
          autoExposure_ = false;  // a chosen exposure stays
        }
        break;
      }
      case GLFW_KEY_A:
        autoExposure_ = !autoExposure_;
        exposureAge_ = 0;
        break;
      case GLFW_KEY_R:
        resetCamera();
        break;
      case GLFW_KEY_P:
        screenshotRequested_ = true;
        break;
      case GLFW_KEY_H:
        panel_->showHelp = !panel_->showHelp;
        break;
      case GLFW_KEY_TAB:
        panel_->visible = !panel_->visible;
        break;
      case GLFW_KEY_C:
        if (comparison_) comparison_->cycleView();
        break;
      case GLFW_KEY_COMMA:
        environments_->step(-1);
        break;
      case GLFW_KEY_PERIOD:
        environments_->step(+1);
        break;
      case GLFW_KEY_EQUAL:
      case GLFW_KEY_KP_ADD:
      case GLFW_KEY_PAGE_UP:
        zoom(0.9f);
        break;
      case GLFW_KEY_MINUS:
      case GLFW_KEY_KP_SUBTRACT:
      case GLFW_KEY_PAGE_DOWN:
        zoom(1.0f / 0.9f);
        break;
      case GLFW_KEY_LEFT:
      case GLFW_KEY_RIGHT:
      case GLFW_KEY_UP:
      case GLFW_KEY_DOWN: {
        const float sx = key == GLFW_KEY_LEFT ? -1.0f : key == GLFW_KEY_RIGHT ? 1.0f : 0.0f;
        const float sy = key == GLFW_KEY_DOWN ? -1.0f : key == GLFW_KEY_UP ? 1.0f : 0.0f;
        if (mods & GLFW_MOD_SHIFT)
          camera_->pan(0.05f * sx, 0.05f * sy);
        else
          camera_->orbit(glm::radians(5.0f) * sx, glm::radians(5.0f) * sy);
        cameraMoved_ = true;
        break;
      }
      default:
        break;
    }
  }

  void zoom(float factor) {
    camera_->zoom(factor);
    cameraMoved_ = true;
  }

  // { and }: the next or previous image of --reference (a report case's reference and modes),
  // shown alone when the live frame was.
  void flipImage(int direction) {
    if (!comparison_) return;
    comparison_->flip(direction);
    if (comparison_->view == ComparisonView::Live) comparison_->view = ComparisonView::Image;
    report("showing " + comparison_->shownLabel());
  }

  // The window title: the scene, and the image compared with when a comparison is on.
  void updateTitle() {
    std::string title = title_;
    if (comparison_ && comparison_->view != ComparisonView::Live)
      title += " | " + std::string(comparisonViewName(comparison_->view)) + ": " + comparison_->shownLabel();
    if (title == shownTitle_) return;
    glfwSetWindowTitle(window_->window(), title.c_str());
    shownTitle_ = title;
  }

  // Takes the window's events in order (window_input.h), up to one after which a frame must be
  // drawn before the rest: a screenshot request (the picture shows what came before it, not what
  // came after it in the same batch) or a resize (a frame at the new size first). The rest wait
  // for the next frame. Mouse input over the panel, and keys while a text field of it is active,
  // are the panel's.
  void handleInput() {
    int windowWidth = 1, windowHeight = 1;
    glfwGetWindowSize(window_->window(), &windowWidth, &windowHeight);
    windowWidth = std::max(windowWidth, 1);
    windowHeight = std::max(windowHeight, 1);
    const bool panelMouse = panel_->wantsMouse(), panelKeyboard = panel_->wantsKeyboard();
    while (std::optional<InputEvent> event = input_.next()) {
      if (const auto* key = std::get_if<KeyPressed>(&*event)) {
        if (!panelKeyboard) handleKey(key->key, key->mods);
        if (screenshotRequested_) return;
      } else if (const auto* button = std::get_if<MouseButton>(&*event)) {
        const int which = button->button;
        if (which != GLFW_MOUSE_BUTTON_LEFT && which != GLFW_MOUSE_BUTTON_RIGHT && which != GLFW_MOUSE_BUTTON_MIDDLE)
          continue;
        buttonsDown_ = button->pressed ? buttonsDown_ | (1u << which) : buttonsDown_ & ~(1u << which);
        if (buttonsDown_ == 0) drag_ = Drag::None;
        if (button->pressed && drag_ == Drag::None && !panelMouse)
          drag_ = which != GLFW_MOUSE_BUTTON_LEFT ? Drag::Pan
                  : comparison_ && comparison_->nearDivider(cursorX_, windowWidth) ? Drag::Divider
                                                                                  : Drag::Orbit;
      } else if (const auto* cursor = std::get_if<CursorMoved>(&*event)) {
        drag(cursor->x, cursor->y, windowWidth, windowHeight);
      } else if (const auto* scroll = std::get_if<Scrolled>(&*event)) {
        if (!panelMouse && drag_ == Drag::None) zoom(std::pow(0.9f, float(scroll->y)));
      } else if (const auto* dropped = std::get_if<FileDropped>(&*event)) {
        open(dropped->file);
      } else if (const auto* resized = std::get_if<FramebufferResized>(&*event)) {
        framebufferWidth_ = resized->width;
        framebufferHeight_ = resized->height;
        return;
      }
    }
  }

  // The cursor moved to (x, y), window coordinates: the drag under way follows it.
  void drag(double x, double y, int windowWidth, int windowHeight) {
    const double dx = x - cursorX_, dy = y - cursorY_;
    cursorX_ = x;
    cursorY_ = y;
    switch (drag_) {
      case Drag::Orbit:
        // A drag across the window's width turns the view half way round.
        camera_->orbit(-float(dx) * glm::pi<float>() / float(windowWidth),
                       float(dy) * glm::pi<float>() / float(windowWidth));
        cameraMoved_ = true;
        break;
      case Drag::Pan:
        camera_->pan(-float(dx) / float(windowHeight), float(dy) / float(windowHeight));
        cameraMoved_ = true;
        break;
      case Drag::Divider:
        comparison_->divider = std::clamp(float(x / windowWidth), 0.0f, 1.0f);
        break;
      case Drag::None:
        break;
    }
  }

  ViewerOptions options_;
  BakedScene bake_;
  FrameSettings settings_;
  std::optional<WindowContext> window_;  // first in, last out: the GL objects need its context
  std::unique_ptr<Renderer> renderer_;
  std::vector<Material> originalMaterials_;
  std::optional<OrbitCamera> camera_;
  std::unique_ptr<ReferenceComparison> comparison_;
  std::unique_ptr<EnvironmentSwitcher> environments_;
  std::unique_ptr<Panel> panel_;
  std::unique_ptr<RenderTarget> target_;
  WindowInput input_;
  Drag drag_ = Drag::None;
  unsigned buttonsDown_ = 0;  // bit GLFW_MOUSE_BUTTON_*: the left, right and middle buttons held
  double cursorX_ = 0.0, cursorY_ = 0.0;       // window coordinates
  int framebufferWidth_ = 0, framebufferHeight_ = 0;  // pixels, from the resize events
  std::string title_, shownTitle_;  // the scene's title; the one the window has now
  bool cameraMoved_ = false, screenshotRequested_ = false;
  std::vector<double> recent_;
  std::string lastScreenshot_;
  static constexpr int kExposureInterval = 8;  // frames between automatic exposure measurements
  bool autoExposure_;
  int exposureAge_ = 0;  // frames since the exposure was measured; 0: measure on the next frame
  std::future<BakedScene> opening_;  // a file being opened
  fs::path openingFile_;
  Clock::time_point openingStart_;
  std::shared_ptr<LoadProgress> openingProgress_;  // shared with the worker opening the file
  std::string openStatus_;
};

std::string lowerExtension(const fs::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace

OpenedKind openedKind(const fs::path& file) {
  const std::string extension = lowerExtension(file);
  if (extension == ".exr" || extension == ".hdr") return OpenedKind::Environment;
  if (extension == ".json" || extension == ".gltf" || extension == ".glb") return OpenedKind::Scene;
  std::error_code error;
  if (fs::is_directory(file, error)) return OpenedKind::Scene;
  return OpenedKind::Unsupported;
}

int runViewer(const ViewerOptions& options) {
  // Bad names fail before anything is loaded or opened.
  parseComparisonView(options.compare);
  if (!options.show.empty()) {
    if (options.references.empty()) failUsage("--show", "only with --reference");
    std::string names;
    bool found = false;
    for (const ComparisonImage& image : options.references) {
      found |= image.name == options.show;
      names += (names.empty() ? "" : ", ") + image.name;
    }
    if (!found)
      failUsage("--show", "no image '" + options.show + "' in " + options.referenceSource + " (expected one of " +
                              names + ")");
  }
  if (!options.screenshot.empty()) screenshotFiles(options.screenshot);
  if (!options.environment.empty() && !fs::is_regular_file(options.environment))
    fail(options.environment, "no such file");
  return Viewer(options).run();
}

}  // namespace iblkit
