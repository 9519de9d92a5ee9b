#pragma once
// What iblkit-report runs and how: image size, modes, the reference's passes and convergence, the
// engine's sampling (docs/report.md).

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit {

struct ReportSettings {
  std::filesystem::path binDir;  // where iblkit-bake, iblkit-trace and iblkit-view are
  std::filesystem::path outDir;  // report.html, report.json and images/
  int width = 320, height = 180;
  std::vector<std::string> modes;     // engine modes to score (iblkit-view --mode)
  int passSpp = 16;                   // samples per pixel of one reference pass
  // Reference passes; even. After the first minPasses the count is aimed at the target from the
  // measured noise (referencePassesFor), at most maxPasses.
  int minPasses = 4, maxPasses = 64;
  // Passes one iblkit-trace run may trace together (a trace stage of up to this many x passSpp
  // samples): fewer program starts, and one scrambled Sobol sequence over all of a stage's samples
  // is better stratified than as many independent sequences of passSpp (about 1.5x lower relMSE
  // at 512 spp than 32 passes of 16, docs/report.md "Reference"). 1: a stage per pass.
  int maxStagePasses = 16;
  // The reference is converged when its estimated relMSE is at most maxReferenceRelMse and at
  // most the larger of negligibleRatio times the best mode's relMSE and negligibleRelMse
  // (referenceTargetRelMse, docs/report.md "Reference").
  // The absolute bound: 1e-3 is 3% RMS relative noise, about where a thumbnail stops looking
  // grainy (the bunny under studio at 10% of its best mode stopped at 0.0094, 10% RMS).
  double maxReferenceRelMse = 1e-3;
  // The reference's noise adds at most this fraction to every mode's measured error.
  double negligibleRatio = 0.1;
  // ...unless that is below this relMSE (1% RMS relative noise): where a mode is nearly exact
  // (the mirror sphere's `mirror`), 10% of its error would ask for thousands of samples to
  // resolve differences no score can see.
  double negligibleRelMse = 1e-4;
  // iblkit-trace --camera-light-samples of the reference passes: environment light samples at the
  // camera ray's first hit (splitting; docs/reference-tracer.md). 2: at equal time as good as 1
  // and 25-35% better than 4 since the environment samples follow the bilinear radiance and the
  // vertex's normal (docs/reference-tracer.md "Noise split").
  int referenceLightSamples = 2;
  // iblkit-bake --bounces of the bakes: the SH transfer's interreflection (the engine's diffuse
  // multi-bounce fit is off with it). 2: docs/report.md "Interreflected transfer" measured 0, 2.
  int bakeBounces = 2;
  // iblkit-bake --ao-area for the bakes: each vertex's visibility rays start over its share of the
  // surface, not at the vertex (docs/baker.md "Area sampling"). The boxes of `pmndrs` and `tiles`
  // are low-poly (about 100 vertices a box): a vertex at a box's corner or edge sees more or less
  // than the face it is interpolated over (docs/report.md "Area sampling in the report's bakes").
  bool bakeAreaSampling = true;
  int benchFrames = 5;  // iblkit-view --bench frames for the frame time; 0: not measured
  // Engine frames shade this many samples per pixel (iblkit-view --samples N --sample-shading), so
  // their pixels average the shading over the pixel as the reference's pixel filter does; 1: one.
  int engineSamples = 4;
  // ...and render K x K pixels per output pixel (iblkit-view --supersample K): 4 x 2 x 2 = 16
  // shaded samples by default, since 4 still alias the mirror sphere's minified reflection.
  int engineSupersample = 2;
  // ...with this texture anisotropy (iblkit-view --anisotropy): 1, isotropic trilinear, because
  // the reference's ray cones are isotropic (docs/reference-tracer.md "Texture filtering"), so the
  // score measures the lighting approximations, not a filter the reference does not model; it
  // also avoids llvmpipe's anisotropic filter, which blurs even head-on (docs/material-model.md
  // "Raster against reference": checker quad FLIP 0.047 at 16 against 0.016 at 1).
  int engineAnisotropy = 1;
  // --sample-shading with engineSamples > 1. The report turns it off for a textured scene
  // (runCase): llvmpipe evaluates the varyings of sample-rate invocations far outside the pixel on
  // surfaces seen at grazing angles (7 pixels' spread on a grazing plane; docs/engine.md "Per-sample
  // shading on llvmpipe"), which smears textures (a grazing checker plane: FLIP 0.41 against the
  // reference with it, 0.05 without; docs/material-model.md "Raster against reference"); the K x K
  // supersampling still shades K^2 points per pixel.
  bool engineSampleShading = true;
  // iblkit-trace --integrator of the reference: path (full global illumination) or direct (one
  // bounce: what the engine's modes model without interreflection), for experiments.
  std::string referenceIntegrator = "path";
};

}  // namespace iblkit
