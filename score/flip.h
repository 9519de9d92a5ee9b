#pragma once
// FLIP, NVIDIA's perceptual difference evaluator for rendered images, written from the papers:
//   LDR-FLIP: Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild, "FLIP: A Difference
//             Evaluator for Alternating Images", HPG 2020 (Proc. ACM CGIT 3(2)).
//   HDR-FLIP: Andersson, Nilsson, Shirley, Akenine-Möller, "Visualizing and Communicating Errors in
//             Rendered Images", Ray Tracing Gems II, chapter 19, 2021.
// The error of a pixel is in [0,1]: 0 means no perceivable difference when flipping between the
// images at the given viewing distance, 1 the largest difference (docs/scoring.md).

#include <vector>

#include "core/image.h"

namespace iblkit {

// Viewing conditions of the FLIP papers: 0.7 m from a 0.7 m wide 3840-pixel display.
inline constexpr float kDefaultPixelsPerDegree = 67.0f;

// A per-pixel FLIP error, row 0 at the top.
struct FlipErrorMap {
  int width = 0, height = 0;
  std::vector<float> error;  // width * height values in [0,1]
};

// LDR-FLIP of two linear RGB images with values in [0,1] (an sRGB PNG decoded to linear; larger
// values are clamped). Alpha is ignored. Both images must have the same size.
FlipErrorMap ldrFlip(const Image& reference, const Image& test,
                     float pixelsPerDegree = kDefaultPixelsPerDegree);

// The exposures HDR-FLIP brackets, in stops: `count` evenly spaced from start to stop.
struct ExposureRange {
  float start = 0.0f, stop = 0.0f;
  int count = 2;
};
// The bracket RTG2 ch. 19 derives from the reference: with x85 the input where the ACES fit
// (flipAces) reaches 0.85, the start exposure brings the reference's largest luminance to x85 and
// the stop exposure its median luminance; count = max(2, ceil(stop - start)).
ExposureRange automaticExposureRange(const Image& reference);
// The bracket from start to stop (stop >= start) with the chapter's count, max(2, ceil(stop - start)).
ExposureRange exposureBracket(float start, float stop);
// The chapter's ACES tone mapper (Narkowicz's fit applied to 0.6 x), clamped to [0,1]. It differs
// from our display curve (tone_curve.h), which omits the 0.6 pre-scale.
float flipAces(float x);

// HDR-FLIP of two linear HDR images: each exposure of the bracket tone mapped with flipAces and
// compared with LDR-FLIP; the result is the per-pixel maximum over the exposures.
FlipErrorMap hdrFlip(const Image& reference, const Image& test, const ExposureRange& exposures,
                     float pixelsPerDegree = kDefaultPixelsPerDegree);

}  // namespace iblkit
