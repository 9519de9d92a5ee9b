#pragma once
// The path-traced reference beside the live frame (iblkit-view --reference REF.exr): a split view
// (live left of a draggable divider, reference right of it, both the whole frame at the same
// camera) or the scorer's relMSE heat map of the difference (difference_heat_map.h). The
// reference is only comparable while the camera is the scene's: the panel says when it is not.
#include <epoxy/gl.h>

#include <filesystem>
#include <string>

#include "core/enum_names.h"
#include "core/image.h"
#include "engine/gl/gpu_textures.h"
#include "engine/gl/renderer.h"
#include "engine/view/difference_heat_map.h"

namespace iblkit {

enum class ComparisonView { Live, Split, Difference };
inline constexpr EnumName<ComparisonView> kComparisonViewNames[] = {
    {ComparisonView::Live, "live"},
    {ComparisonView::Split, "split"},
    {ComparisonView::Difference, "difference"}};
const char* comparisonViewName(ComparisonView view);
// A name of the table above; throws Error("--compare: unknown view 'x' (expected one of ...)")
// otherwise.
ComparisonView parseComparisonView(const std::string& name);

class ReferenceComparison {
 public:
  // Reads the reference (OpenEXR, linear radiance, e.g. iblkit-trace's output) and uploads it;
  // starts in the split view. Needs a current OpenGL context. Throws Error("<file>: <problem>").
  explicit ReferenceComparison(const std::filesystem::path& file);
  ReferenceComparison(const ReferenceComparison&) = delete;
  ReferenceComparison& operator=(const ReferenceComparison&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  const std::filesystem::path& file() const { return file_; }

  ComparisonView view = ComparisonView::Split;
  float divider = 0.5f;     // split view: the divider's position, a fraction of the width
  float heatMapMax = 1.0f;  // difference view: the relMSE term at the top of the colour map
  void cycleView();         // Live -> Split -> Difference -> Live
  // Whether window x coordinate `x` (pixels from the left) is close enough to grab the divider.
  bool nearDivider(double x, int width) const;

  // Draws the view into the viewport (0, 0, width, height) of the bound draw framebuffer: the live
  // frame (`liveTexture`, linear radiance) tone-mapped with `settings`, the reference with the same
  // exposure and curve, or the heat map. Both images are stretched over the viewport.
  void present(Renderer& renderer, GLuint liveTexture, const FrameSettings& settings, int width, int height);

 private:
  std::filesystem::path file_;
  int width_ = 0, height_ = 0;
  GlTexture texture_;
  DifferenceHeatMap heatMap_;
};

}  // namespace iblkit
