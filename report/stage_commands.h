#pragma once
// The commands of the report's stages, as a user would type them (docs/report.md): a scene's
// visibility, the bake, the engine frames of a group of modes and one reference pass per seed. Each names its outputs under
// kStageFolder, so its cache key (stageKey) is hashed from exactly what runs.

#include <filesystem>
#include <string>
#include <vector>

#include "report/case_modes.h"
#include "report/report_settings.h"
#include "report/stage_command.h"

namespace iblkit {

// What a scene's images depend on besides the arguments: the scene file, every model file it
// names, every texture image file its materials read (files beside a glTF, a scene file's
// texture overrides) and the environment map, whose bytes go into the key of each stage that
// reads them; whether the scene has textures (the reference then traces with the engine frame's
// texture footprint) and whether some material has a glTF occlusion texture (case_modes.h); the
// scene's environment rotation and intensity, which the bake applies to the map.
struct CaseInputs {
  std::filesystem::path sceneFile, environmentFile;
  std::vector<std::filesystem::path> files;  // the scene, its model and image files, the environment map
  bool textured = false;
  bool occlusionTexture = false;
  SceneLobes lobes;  // which modes apply (case_modes.h)
  float environmentRotationDegrees = 0.0f, environmentIntensity = 1.0f;
};
CaseInputs caseInputs(const std::filesystem::path& sceneFile, const std::filesystem::path& environmentFile);

// iblkit-bake SCENE --bounces N [--ao-area] --visibility-only -o {stage}/bake: the scene's per-vertex
// visibility, which does not depend on the map (baker/reused_visibility.h): one stage per scene,
// its key from the scene's files alone, read by the bakes of every map.
StageCommand visibilityCommand(const ReportSettings& settings, const CaseInputs& inputs);

// iblkit-bake --env ENV --env-rotation R --env-intensity I --environment-only -o {stage}/bake: the
// map's environment stages under the scene's rotation and intensity, which do not depend on the
// scene (baker/reused_environment.h): one stage per map (and rotation and intensity), its key from
// the map's bytes alone, read by the bakes of every scene.
StageCommand environmentCommand(const ReportSettings& settings, const CaseInputs& inputs);

// iblkit-bake SCENE --env ENV --bounces N [--ao-area] [--visibility-from VISIBILITY]
// [--environment-from ENVIRONMENT] -o {stage}/bake: the suns' bounce, with the per-vertex visibility
// of the visibility stage whose folder in the cache is `visibility` and the environment stages of
// the environment stage whose folder is `environment` (named under kCacheFolder; empty: computed
// here).
StageCommand bakeCommand(const ReportSettings& settings, const CaseInputs& inputs,
                         const std::filesystem::path& visibility = {}, const std::filesystem::path& environment = {});

// iblkit-view BAKE --headless -o {stage}/frame-{mode}.exr --mode MODE,MODE... at the report's size,
// samples, supersampling and bench frames: the frames of several modes from one process (each to
// viewFrameFile(mode)), their bench frames timed in turn. `modes` must share every other option
// (one of viewGroups). `bake` is the bake stage's folder in the cache, named by its key: the command
// names it under kCacheFolder.
StageCommand viewCommand(const ReportSettings& settings, const std::filesystem::path& bake,
                         const std::vector<std::string>& modes);

// `modes` split into the groups that one iblkit-view can render together: those whose commands
// differ only in --mode (lights-shadowed supersamples without sample shading), each group in the
// order of `modes`, the groups in the order of their first mode.
std::vector<std::vector<std::string>> viewGroups(const ReportSettings& settings, const std::vector<std::string>& modes);

// The file a view stage writes mode's frame to, in its folder.
std::string viewFrameFile(const std::string& mode);

// iblkit-trace SCENE --env ENV: the reference pass with `seed` ({stage}/beauty.exr and depth.exr;
// pass 0 also writes {stage}/normal.exr, for the mask's normals), with --camera-light-samples K
// unless K = settings.referenceLightSamples is 1 (whose command and key stay those of before). A textured scene is traced with
// --texture-footprint 1/K, K the engine's --supersample: the engine's texture lookups take their
// level of detail from the derivatives of its K x K finer pixels, so the reference's camera ray
// cones spread over that pixel too (reference/renderer.h, textureFootprint). An untextured scene's
// command (and cache key) does not depend on K.
// `passes` passes of settings.passSpp samples in one run (reference_passes.h groups them).
StageCommand traceCommand(const ReportSettings& settings, const CaseInputs& inputs, int seed, int passes = 1);

}  // namespace iblkit
