#include "engine/view/reference_comparison.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/image_io.h"

namespace iblkit {

const char* comparisonViewName(ComparisonView view) {
  // The table's names are literals, so their data is null-terminated.
  return enumNameOf(kComparisonViewNames, view).data();
}

ComparisonView parseComparisonView(const std::string& name) {
  return parseEnumName(kComparisonViewNames, name, "--compare", "view");
}

namespace {

// GL's texture row 0 is the bottom of the screen (present.frag samples ndc * 0.5 + 0.5), Image's
// row 0 is the top: the rows are turned over for the upload.
Image bottomRowFirst(const Image& image) {
  Image flipped(image.width(), image.height());
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) flipped.at(x, image.height() - 1 - y) = image.at(x, y);
  return flipped;
}

}  // namespace

ReferenceComparison::ReferenceComparison(const std::filesystem::path& file) : file_(file) {
  const Image reference = readExr(file);
  width_ = reference.width();
  height_ = reference.height();
  texture_ = uploadTable(bottomRowFirst(reference));
}

void ReferenceComparison::cycleView() {
  view = view == ComparisonView::Live    ? ComparisonView::Split
         : view == ComparisonView::Split ? ComparisonView::Difference
                                         : ComparisonView::Live;
}

bool ReferenceComparison::nearDivider(double x, int width) const {
  return view == ComparisonView::Split && std::abs(x - double(divider) * width) <= 6.0;
}

void ReferenceComparison::present(Renderer& renderer, GLuint liveTexture, const FrameSettings& settings,
                                  int width, int height) {
  if (view == ComparisonView::Live) {
    renderer.presentToneMapped(liveTexture, settings, 0, 0, width, height);
    return;
  }
  if (view == ComparisonView::Difference) {
    heatMap_.draw(liveTexture, texture_.id(), heatMapMax, width, height);
    return;
  }
  // Split: the live frame left of the divider, the reference right of it, a 2-pixel white line.
  const int split = std::clamp(int(std::lround(divider * float(width))), 0, width);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, split, height);
  renderer.presentToneMapped(liveTexture, settings, 0, 0, width, height);
  glScissor(split, 0, width - split, height);
  renderer.presentToneMapped(texture_.id(), settings, 0, 0, width, height);
  glScissor(std::max(0, split - 1), 0, 2, height);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace iblkit
