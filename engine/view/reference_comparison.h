#pragma once
// The path-traced reference beside the live frame (iblkit-view --reference): a split view (live
// left of a draggable divider, the image right of it, both the whole frame at the same camera),
// the scorer's relMSE heat map of the difference (difference_heat_map.h), or the image alone.
// The comparison holds one image (a reference .exr) or several (a report case: its reference and
// each mode's frame, report/report_case_images.h), and shows one of them at a time; flipping
// steps through them. An image is only comparable while the camera is the scene's: the panel
// says when it is not.
#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "core/enum_names.h"
#include "core/image.h"
#include "engine/gl/gpu_textures.h"
#include "engine/gl/renderer.h"
#include "engine/view/difference_heat_map.h"

namespace iblkit {

enum class ComparisonView { Live, Split, Difference, Image };
inline constexpr EnumName<ComparisonView> kComparisonViewNames[] = {
    {ComparisonView::Live, "live"},
    {ComparisonView::Split, "split"},
    {ComparisonView::Difference, "difference"},
    {ComparisonView::Image, "image"}};
const char* comparisonViewName(ComparisonView view);
// A name of the table above; throws Error("--compare: unknown view 'x' (expected one of ...)")
// otherwise.
ComparisonView parseComparisonView(const std::string& name);

// One image to compare the live frame with: linear radiance (OpenEXR's, or a report's), rows top
// to bottom; its name ("reference", a mode) and a line on it for the panel ("mean FLIP 0.041").
struct ComparisonImage {
  std::string name, detail;
  Image image;
};

// Where an imageWidth x imageHeight image goes in a width x height frame rendered with the same
// vertical field of view: the full height, centred, imageWidth x height / imageHeight wide, so
// that its pixels lie on the live frame's whatever the window's shape (a wider window shows more
// of the scene at the sides, beyond the image; a narrower one cuts the image's sides off).
struct ViewportRect {
  int x = 0, y = 0, width = 0, height = 0;
};
ViewportRect imageViewport(int imageWidth, int imageHeight, int width, int height);

class ReferenceComparison {
 public:
  // Uploads `images` (at least one, all of one size; else Error naming `source`), shows the
  // first, starts in the split view. `source` names where they came from, for the panel (the
  // .exr, or the report and case). Needs a current OpenGL context.
  ReferenceComparison(std::vector<ComparisonImage> images, std::string source);
  ReferenceComparison(const ReferenceComparison&) = delete;
  ReferenceComparison& operator=(const ReferenceComparison&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  const std::string& source() const { return source_; }
  int count() const { return int(images_.size()); }
  const std::string& name(int index) const { return images_[std::size_t(index)].name; }
  const std::string& detail(int index) const { return images_[std::size_t(index)].detail; }
  int shown() const { return shown_; }
  // "sh (3 of 9)": the image shown, for the panel, the window title and stderr.
  std::string shownLabel() const;
  // Shows image `index` (out of range: ignored) or the next (+1) / previous (-1), wrapping round.
  void show(int index);
  void flip(int direction);
  // The index of the image called `name`; -1 when there is none.
  int find(const std::string& name) const;

  ComparisonView view = ComparisonView::Split;
  float divider = 0.5f;     // split view: the divider's position, a fraction of the width
  float heatMapMax = 1.0f;  // difference view: the relMSE term at the top of the colour map
  void cycleView();         // Live -> Split -> Difference -> Image -> Live
  // Whether window x coordinate `x` (from the left, of a window `width` wide) is close enough to
  // grab the divider.
  bool nearDivider(double x, int width) const;

  // Draws the view into the viewport (0, 0, width, height) of the bound draw framebuffer: the live
  // frame (`liveTexture`, linear radiance, width x height) tone-mapped with `settings`, the image
  // shown with the same exposure and curve in imageViewport (black around it), or the heat map
  // over the image's rectangle.
  void present(Renderer& renderer, GLuint liveTexture, const FrameSettings& settings, int width, int height);

 private:
  struct Uploaded {
    std::string name, detail;
    GlTexture texture;
  };
  std::vector<Uploaded> images_;
  std::string source_;
  int width_ = 0, height_ = 0;
  int shown_ = 0;
  DifferenceHeatMap heatMap_;
};

}  // namespace iblkit
