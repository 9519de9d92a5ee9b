// Where the comparison draws its image when the window's shape is not the image's, and how much
// the panel is scaled on a high-DPI screen (no OpenGL: the maths alone).
#include "engine/view/reference_comparison.h"

#include <gtest/gtest.h>

#include "engine/view/panel.h"

namespace iblkit {
namespace {

TEST(ReferenceComparison, TheImageKeepsTheLiveFramesScaleWhateverTheWindowsShape) {
  // Same shape: the whole window.
  const ViewportRect same = imageViewport(160, 120, 160, 120);
  EXPECT_EQ(same.x, 0);
  EXPECT_EQ(same.y, 0);
  EXPECT_EQ(same.width, 160);
  EXPECT_EQ(same.height, 120);
  // Twice the size: twice the pixels, still the whole window.
  EXPECT_EQ(imageViewport(160, 120, 320, 240).width, 320);
  // Wider: the full height, centred, the sides beyond the image.
  const ViewportRect wide = imageViewport(160, 120, 300, 120);
  EXPECT_EQ(wide.x, 70);
  EXPECT_EQ(wide.width, 160);
  EXPECT_EQ(wide.height, 120);
  // Narrower: the image's sides are cut off (the rectangle starts left of the window).
  const ViewportRect narrow = imageViewport(160, 120, 100, 150);
  EXPECT_EQ(narrow.width, 200);
  EXPECT_EQ(narrow.x, -50);
  EXPECT_EQ(narrow.height, 150);
}

TEST(ReferenceComparison, ThePanelIsScaledByWhatTheFramebufferDoesNotAlreadyHave) {
  EXPECT_EQ(panelScale(1.0f, 800, 800), 1.0f);   // an ordinary screen
  EXPECT_EQ(panelScale(2.0f, 800, 800), 2.0f);   // X11 at 192 dpi: framebuffer = window
  EXPECT_EQ(panelScale(2.0f, 800, 1600), 1.0f);  // a Retina Mac: the framebuffer has twice the pixels
  EXPECT_EQ(panelScale(1.5f, 800, 800), 1.5f);
  EXPECT_EQ(panelScale(0.0f, 800, 800), 1.0f);  // nothing known
  EXPECT_EQ(panelScale(1.0f, 0, 0), 1.0f);      // minimised
}

}  // namespace
}  // namespace iblkit
