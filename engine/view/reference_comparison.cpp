#include "engine/view/reference_comparison.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace iblkit {

const char* comparisonViewName(ComparisonView view) {
  // The table's names are literals, so their data is null-terminated.
  return enumNameOf(kComparisonViewNames, view).data();
}

ComparisonView parseComparisonView(const std::string& name) {
  return parseEnumName(kComparisonViewNames, name, "--compare", "view");
}

ViewportRect imageViewport(int imageWidth, int imageHeight, int width, int height) {
  const int w =
      std::max(1, int(std::lround(double(imageWidth) * double(height) / double(std::max(imageHeight, 1)))));
  return {(width - w) / 2, 0, w, height};
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

ReferenceComparison::ReferenceComparison(std::vector<ComparisonImage> images, std::string source)
    : source_(std::move(source)) {
  if (images.empty()) throw Error(source_ + ": no image to compare with");
  width_ = images.front().image.width();
  height_ = images.front().image.height();
  for (ComparisonImage& image : images) {
    if (image.image.width() != width_ || image.image.height() != height_)
      throw Error(source_ + ": image '" + image.name + "' differs in size from '" + images.front().name +
                  "'");
    images_.push_back(
        {std::move(image.name), std::move(image.detail), uploadTable(bottomRowFirst(image.image))});
  }
}

std::string ReferenceComparison::shownLabel() const {
  return name(shown_) + " (" + std::to_string(shown_ + 1) + " of " + std::to_string(count()) + ")";
}

void ReferenceComparison::show(int index) {
  if (index >= 0 && index < count()) shown_ = index;
}

void ReferenceComparison::flip(int direction) {
  shown_ = ((shown_ + direction) % count() + count()) % count();
}

int ReferenceComparison::find(const std::string& wanted) const {
  for (int i = 0; i < count(); ++i)
    if (name(i) == wanted) return i;
  return -1;
}

void ReferenceComparison::cycleView() {
  view = view == ComparisonView::Live         ? ComparisonView::Split
         : view == ComparisonView::Split      ? ComparisonView::Difference
         : view == ComparisonView::Difference ? ComparisonView::Image
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
  const GLuint image = images_[std::size_t(shown_)].texture.id();
  const ViewportRect rect = imageViewport(width_, height_, width, height);
  // Black where the window reaches beyond the image (a window wider than the image's shape).
  auto clearBlack = [](int x, int w, int h) {
    glScissor(x, 0, w, h);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  };
  glEnable(GL_SCISSOR_TEST);
  if (view == ComparisonView::Difference || view == ComparisonView::Image) {
    clearBlack(0, width, height);
    glDisable(GL_SCISSOR_TEST);
    if (view == ComparisonView::Difference)
      heatMap_.draw(liveTexture, image, heatMapMax, width, height, rect.x, rect.y, rect.width, rect.height);
    else
      renderer.presentToneMapped(image, settings, rect.x, rect.y, rect.width, rect.height);
    return;
  }
  // Split: the live frame left of the divider, the image right of it, a 2-pixel white line.
  const int split = std::clamp(int(std::lround(divider * float(width))), 0, width);
  glScissor(0, 0, split, height);
  renderer.presentToneMapped(liveTexture, settings, 0, 0, width, height);
  clearBlack(split, width - split, height);
  glScissor(split, 0, width - split, height);
  renderer.presentToneMapped(image, settings, rect.x, rect.y, rect.width, rect.height);
  glScissor(std::max(0, split - 1), 0, 2, height);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace iblkit
