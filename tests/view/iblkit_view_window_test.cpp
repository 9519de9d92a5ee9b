// End-to-end tests of iblkit-view's window (build/bin) under a virtual X server (xvfb-run, from
// Debian's xvfb and xauth packages; llvmpipe through GLX), on a small bake of the bundled mirror
// sphere scene: frames render, a screenshot matches the headless frame, the reference split and
// difference views show what they should, and a missing display or bake is one line and exit 1;
// real input events (xdotool, drive_window.sh) orbit, zoom, switch the mode, resize the window and
// flip through a report case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

#include "core/auto_exposure.h"
#include "core/image_io.h"
#include "support/report_output.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 160, kHeight = 120;

using test::shellQuoted;

struct ProgramRun {
  int status = 0;
  std::string output;
};

ProgramRun run(const std::string& command) {
  ProgramRun result;
  result.status = test::runCommand(command, &result.output);
  return result;
}

std::string program(const std::string& name) { return shellQuoted(test::binDir() / name); }

// iblkit-view in a window on a fresh virtual display (-a: the first free display number; Debian's
// xvfb-run tries the next one if another test took it meanwhile).
std::string inWindow(const std::string& arguments) {
  return "xvfb-run -a -s '-screen 0 640x480x24' " + program("iblkit-view") + " " + arguments;
}

class IblkitViewWindow : public testing::Test {
 protected:
  void SetUp() override {
    const fs::path scene = test::assetsDir() / "scenes" / "mirror_sphere.json";
    if (!fs::exists(test::assetsDir() / "hdri" / "sky.exr")) GTEST_SKIP() << "assets not fetched";
    ASSERT_EQ(run("command -v xvfb-run >/dev/null").status, 0)
        << "xvfb-run is missing: install xvfb and xauth (scripts/setup.sh)";
    dir_ = test::scratchDir();
    bake_ = dir_ / "bake";
    const ProgramRun bake = run(program("iblkit-bake") + " " + shellQuoted(scene) + " -o " +
                                shellQuoted(bake_) + " --ao-rays 4 --specular-samples 16 --lut-size 16");
    ASSERT_EQ(bake.status, 0) << bake.output;
  }

  // The window's common arguments: small, no environment folder to list.
  std::string windowArguments(const std::string& extra) const {
    return shellQuoted(bake_) + " --width " + std::to_string(kWidth) + " --height " +
           std::to_string(kHeight) + " --env-dir " + shellQuoted(dir_ / "no-maps") + " " + extra;
  }

  Image renderHeadless(const std::string& name) const {
    const fs::path out = dir_ / name;
    const ProgramRun r =
        run(program("iblkit-view") + " " + shellQuoted(bake_) + " --headless -o " + shellQuoted(out) +
            " --width " + std::to_string(kWidth) + " --height " + std::to_string(kHeight));
    EXPECT_EQ(r.status, 0) << r.output;
    return readExr(out);
  }

  fs::path dir_, bake_;
};

bool isMagenta(const glm::vec4& p) { return p.g < 0.01f && p.r > 0.3f && p.b > 0.3f; }

float maxComponent(const glm::vec4& p) { return std::max({p.r, p.g, p.b}); }

TEST_F(IblkitViewWindow, RendersFramesAndItsScreenshotIsTheHeadlessFrame) {
  const fs::path shot = dir_ / "shot.png";
  const ProgramRun r = run(inWindow(windowArguments("--frames 3 --screenshot " + shellQuoted(shot))));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("3 frames, 160x120"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("median frame time"), std::string::npos) << r.output;

  // The EXR: the live frame's radiance, the sphere covered and lit everywhere.
  const Image radiance = readExr(dir_ / "shot.exr");
  ASSERT_EQ(radiance.width(), kWidth);
  ASSERT_EQ(radiance.height(), kHeight);
  int covered = 0;
  for (const glm::vec4& p : radiance.pixels()) {
    ASSERT_TRUE(std::isfinite(p.r + p.g + p.b));
    if (p.a == 1.0f) {
      ++covered;
      EXPECT_GT(p.r + p.g + p.b, 1e-3f);
    }
  }
  EXPECT_GT(covered, 2000);
  EXPECT_LT(covered, kWidth * kHeight / 2);

  // The PNG: what the window showed, not one colour.
  const Image shown = readPng(shot);
  ASSERT_EQ(shown.width(), kWidth);
  std::set<std::tuple<int, int, int>> colours;
  for (const glm::vec4& p : shown.pixels())
    colours.insert({int(std::lround(p.r * 255)), int(std::lround(p.g * 255)), int(std::lround(p.b * 255))});
  EXPECT_GT(colours.size(), 200u);

  // The window starts at the scene's camera: its frame is iblkit-view --headless's, up to the
  // rounding of the orbit camera (a few silhouette pixels may flip).
  const Image headless = renderHeadless("headless.exr");
  int differing = 0;
  for (std::size_t i = 0; i < headless.pixels().size(); ++i) {
    const glm::vec4 a = radiance.pixels()[i], b = headless.pixels()[i];
    if (maxComponent(glm::abs(a - b)) > 1e-3f * (1.0f + maxComponent(b))) ++differing;
  }
  EXPECT_LT(differing, kWidth * kHeight / 100) << differing << " pixels differ";
}

TEST_F(IblkitViewWindow, ReferenceSplitViewShowsLiveLeftAndReferenceRight) {
  const fs::path reference = dir_ / "magenta.exr";
  writeExr(reference, Image(kWidth, kHeight, glm::vec4(2.0f, 0.0f, 2.0f, 1.0f)),
           {.pixelType = PixelType::Float});
  const fs::path shot = dir_ / "split";
  const ProgramRun r = run(inWindow(windowArguments("--reference " + shellQuoted(reference) +
                                                    " --frames 2 --screenshot " + shellQuoted(shot))));
  ASSERT_EQ(r.status, 0) << r.output;
  const Image shown = readPng(fs::path(shot).concat(".png"));
  ASSERT_EQ(shown.width(), kWidth);
  int leftMagenta = 0, rightMagenta = 0, dividerWhite = 0, leftCount = 0, rightCount = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const glm::vec4 p = shown.at(x, y);
      if (x < kWidth / 2 - 8) leftMagenta += isMagenta(p), ++leftCount;
      if (x >= kWidth / 2 + 8) rightMagenta += isMagenta(p), ++rightCount;
      if (x == kWidth / 2) dividerWhite += p.r > 0.95f && p.g > 0.95f && p.b > 0.95f;
    }
  EXPECT_LT(leftMagenta, leftCount / 20) << "the live half";
  EXPECT_EQ(rightMagenta, rightCount) << "the reference half";
  EXPECT_EQ(dividerWhite, kHeight) << "the divider";
  // The EXR stays the live frame's radiance, not the composite.
  const Image radiance = readExr(fs::path(shot).concat(".exr"));
  int liveMagenta = 0;
  for (int y = 0; y < kHeight; ++y) liveMagenta += isMagenta(radiance.at(kWidth - 1, y));
  EXPECT_LT(liveMagenta, kHeight / 2);
}

TEST_F(IblkitViewWindow, DifferenceViewIsBlackAgainstItselfAndBrightAgainstAnotherImage) {
  const Image headless = renderHeadless("same.exr");
  const fs::path magenta = dir_ / "magenta.exr";
  writeExr(magenta, Image(kWidth, kHeight, glm::vec4(2.0f, 0.0f, 2.0f, 1.0f)),
           {.pixelType = PixelType::Float});
  auto blackFraction = [&](const fs::path& reference, const std::string& name) {
    const fs::path shot = dir_ / name;
    const ProgramRun r =
        run(inWindow(windowArguments("--reference " + shellQuoted(reference) +
                                     " --compare difference --frames 2 --screenshot " + shellQuoted(shot))));
    EXPECT_EQ(r.status, 0) << r.output;
    const Image shown = readPng(shot);
    int black = 0;
    for (const glm::vec4& p : shown.pixels()) black += maxComponent(p) < 0.02f;
    return double(black) / double(shown.pixelCount());
  };
  // Not "same.png": its screenshot pair same.exr would replace the reference (refused).
  EXPECT_GT(blackFraction(dir_ / "same.exr", "same-shot.png"), 0.97);
  EXPECT_LT(blackFraction(magenta, "other.png"), 0.05);
}

// --env switches the environment on the worker thread; a scripted run waits for it before the
// screenshot: a constant red map makes the sky and the mirror red.
TEST_F(IblkitViewWindow, SwitchesToAnotherEnvironment) {
  const fs::path red = dir_ / "red.exr";
  writeExr(red, Image(64, 32, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)), {.pixelType = PixelType::Float});
  const fs::path shot = dir_ / "red_shot.exr";
  const ProgramRun r = run(inWindow(
      windowArguments("--env " + shellQuoted(red) + " --frames 1 --screenshot " + shellQuoted(shot))));
  ASSERT_EQ(r.status, 0) << r.output;
  const Image radiance = readExr(shot);
  int sky = 0, mirror = 0;
  for (const glm::vec4& p : radiance.pixels()) {
    EXPECT_NEAR(p.g, 0.0f, 1e-3f);
    EXPECT_NEAR(p.b, 0.0f, 1e-3f);
    if (p.a == 0.0f) sky += std::abs(p.r - 1.0f) < 1e-3f;
    if (p.a == 1.0f) mirror += p.r > 0.5f;
  }
  EXPECT_GT(sky, kWidth * kHeight / 2);
  EXPECT_GT(mirror, 2000);
  // A missing map: named, exit 1.
  const ProgramRun missing =
      run(program("iblkit-view") + " " + windowArguments("--env " + shellQuoted(dir_ / "no.exr")));
  EXPECT_EQ(missing.status, 1);
  EXPECT_TRUE(missing.output.ends_with("iblkit-view: " + (dir_ / "no.exr").string() + ": cannot open: No such file or directory\n"))
      << missing.output;
}

TEST_F(IblkitViewWindow, NoDisplayIsOneLineAndExitStatus1) {
  const fs::path shot = dir_ / "never.png";
  const ProgramRun r = run("env -u DISPLAY -u WAYLAND_DISPLAY " + program("iblkit-view") + " " +
                           windowArguments("--frames 1 --screenshot " + shellQuoted(shot)));
  EXPECT_EQ(r.status, 1) << r.output;
  // Warnings of the bake's environment map may come first (sky.exr has a few negative pixels).
  std::vector<std::string> errors;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);)
    if (line.find(": warning: ") == std::string::npos) errors.push_back(line);
  ASSERT_EQ(errors.size(), 1u) << r.output;
  EXPECT_EQ(errors[0].rfind("iblkit-view: cannot open a window (", 0), 0u) << r.output;
  EXPECT_NE(errors[0].find("use --headless)"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(shot));
  EXPECT_FALSE(fs::exists(dir_ / "never.exr"));
}

TEST_F(IblkitViewWindow, BadInputFailsBeforeAWindowOpens) {
  // A missing bake: readBakeFolder's error, as --headless prints it.
  const fs::path missing = dir_ / "missing";
  const ProgramRun window = run(program("iblkit-view") + " " + shellQuoted(missing));
  const ProgramRun headless = run(program("iblkit-view") + " " + shellQuoted(missing) + " --headless -o " +
                                  shellQuoted(dir_ / "x.exr"));
  EXPECT_EQ(window.status, 1);
  EXPECT_EQ(window.output, headless.output);
  EXPECT_EQ(window.output.rfind("iblkit-view: " + missing.string() + ": ", 0), 0u) << window.output;
  // A missing reference, a bad view name, a bad screenshot name: named, without a display.
  const ProgramRun reference =
      run(program("iblkit-view") + " " + windowArguments("--reference " + shellQuoted(dir_ / "none.exr")));
  EXPECT_EQ(reference.status, 1);
  EXPECT_TRUE(reference.output.ends_with("iblkit-view: " + (dir_ / "none.exr").string() +
                                         ": cannot open: No such file or directory\n"))
      << reference.output;
  const ProgramRun view = run(program("iblkit-view") + " " + windowArguments("--compare sideways"));
  EXPECT_EQ(view.status, 2);  // a usage error (cli/program.h)
  EXPECT_EQ(view.output,
            "iblkit-view: --compare: unknown view 'sideways' (expected one of live, split, difference, image)\n");
  const ProgramRun shot =
      run(program("iblkit-view") + " " + windowArguments("--screenshot " + shellQuoted(dir_ / "a.jpg")));
  EXPECT_EQ(shot.status, 1);
  EXPECT_NE(shot.output.find("unsupported screenshot format"), std::string::npos) << shot.output;
  // Window flags with --headless, headless flags without it.
  EXPECT_EQ(run(program("iblkit-view") + " " + shellQuoted(bake_) + " --headless -o " +
                shellQuoted(dir_ / "h.exr") + " --frames 2")
                .status,
            2);
  EXPECT_EQ(run(program("iblkit-view") + " " + shellQuoted(bake_) + " --bench 2").status, 2);
}

}  // namespace
}  // namespace iblkit

namespace iblkit {
namespace {

// The mean display value of a PNG (sRGB-encoded, 0..1).
double meanValue(const Image& png) {
  double sum = 0.0;
  for (const glm::vec4& p : png.pixels()) sum += (p.r + p.g + p.b) / 3.0;
  return sum / double(png.pixels().size());
}

TEST_F(IblkitViewWindow, HeadlessModelWithEnvAgreesWithTheSameSceneFileAndABadMapIsOneLine) {
  const fs::path model = test::assetsDir() / "models" / "suzi.glb";
  const fs::path map = test::assetsDir() / "hdri" / "studio.exr";
  const fs::path scene = dir_ / "suzi_bare.json";
  {
    std::ofstream out(scene);
    out << "{\"models\": [{\"file\": \"" << fs::absolute(model).string() << "\"}], \"environment\": {\"file\": \""
        << fs::absolute(map).string() << "\"}}";
  }
  const std::string size = " --width 80 --height 60 --ao-rays 4";
  ProgramRun r = run(program("iblkit-view") + " " + shellQuoted(model) + " --env " + shellQuoted(map) +
                     " --headless -o " + shellQuoted(dir_ / "model.exr") + size);
  ASSERT_EQ(r.status, 0) << r.output;
  r = run(program("iblkit-view") + " " + shellQuoted(scene) + " --headless -o " + shellQuoted(dir_ / "scene.exr") + size);
  ASSERT_EQ(r.status, 0) << r.output;
  const Image a = readExr(dir_ / "model.exr"), b = readExr(dir_ / "scene.exr");
  ASSERT_EQ(a.pixels().size(), b.pixels().size());
  double lit = 0.0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    EXPECT_LE(maxComponent(glm::abs(a.pixels()[i] - b.pixels()[i])), 1e-4f * (1.0f + maxComponent(b.pixels()[i])));
    lit += maxComponent(a.pixels()[i]);
  }
  EXPECT_GT(lit, 1.0);
  const fs::path missing = dir_ / "missing.exr";
  r = run(program("iblkit-view") + " " + shellQuoted(model) + " --env " + shellQuoted(missing) + " --headless -o " +
          shellQuoted(dir_ / "bad.exr") + size);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.output, "iblkit-view: " + missing.string() + ": cannot open: No such file or directory\n");
  EXPECT_FALSE(fs::exists(dir_ / "bad.exr"));
}

TEST_F(IblkitViewWindow, StartsWellExposedOnSuziAndAGivenExposureIsLocked) {
  const fs::path scene = test::assetsDir() / "scenes" / "suzi.json";
  const std::string common = shellQuoted(scene) + " --width 160 --height 90 --ao-rays 4 --env-dir " +
                             shellQuoted(dir_ / "no-maps") + " --frames 3 --screenshot ";
  ProgramRun r = run(inWindow(common + shellQuoted(dir_ / "auto.png")));
  ASSERT_EQ(r.status, 0) << r.output;
  r = run(inWindow(common + shellQuoted(dir_ / "locked.png") + " --exposure 3"));  // given: locked there
  ASSERT_EQ(r.status, 0) << r.output;
  // The exposure printed is the key exposure of the frame's radiance (the screenshot's EXR); the
  // frame is then near middle grey on average (0.18 is about 0.46 in sRGB).
  const Image radiance = readExr(dir_ / "auto.exr");
  std::ostringstream expected;
  expected << std::fixed << std::setprecision(2) << "exposure " << keyExposure(radiance) << " (auto)";
  ProgramRun automatic = run(inWindow(common + shellQuoted(dir_ / "auto2.png")));
  EXPECT_NE(automatic.output.find(expected.str()), std::string::npos) << automatic.output << " vs " << expected.str();
  EXPECT_LT(keyExposure(radiance), -0.5f);  // studio at exposure 0 is too bright for the key
  const double shown = meanValue(readPng(dir_ / "auto.png"));
  EXPECT_GT(shown, 0.3);
  EXPECT_LT(shown, 0.65);
  EXPECT_NE(r.output.find("exposure 3.00 (locked)"), std::string::npos) << r.output;
}

TEST_F(IblkitViewWindow, OpeningABadFileSaysSoAndKeepsTheSceneAMapSwitches) {
  const fs::path shot = dir_ / "opened.exr";
  const fs::path red = dir_ / "red.exr";
  writeExr(red, Image(8, 4, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)), {.pixelType = PixelType::Float});
  const ProgramRun r = run(inWindow(windowArguments("--frames 3 --screenshot " + shellQuoted(shot) + " --open " +
                                                    shellQuoted(dir_ / "nothing.glb") + " " +
                                                    shellQuoted(dir_ / "notes.txt") + " " + shellQuoted(red))));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("cannot open: " + (dir_ / "nothing.glb").string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((dir_ / "notes.txt").string() + ": cannot open (expected"), std::string::npos) << r.output;
  // The map dropped last was switched to: the sky is red.
  const Image radiance = readExr(shot);
  const glm::vec4 corner = radiance.pixels()[0];
  EXPECT_GT(corner.r, 0.1f);
  EXPECT_LT(corner.g, 0.01f * corner.r);
}

}  // namespace
}  // namespace iblkit

namespace iblkit {
namespace {

// The screenshots (EXR of the radiance, PNG of the view) a run wrote with P, in order.
struct Shot {
  fs::path exr, png;
};

struct DrivenRun {
  ProgramRun run;   // drive_window.sh's status and output (xdotool's, e.g. getwindowname)
  std::string log;  // iblkit-view's stdout and stderr
  std::vector<Shot> shots;
};

// iblkit-view `arguments` in a window on a fresh virtual display, driven by real X input events
// (xdotool through tests/view/drive_window.sh, `events` one command a line), run in `dir` so
// that P's screenshots land there; Esc at the end. At most 60 s in all.
DrivenRun drive(const fs::path& dir, const std::string& events, const std::string& arguments) {
  const fs::path script = IBLKIT_DRIVE_WINDOW;
  std::ofstream(dir / "events") << events;
  DrivenRun result;
  result.run = run("cd " + shellQuoted(dir) + " && timeout 60 xvfb-run -a -s '-screen 0 640x480x24' bash " +
                   shellQuoted(script) + " log events " + program("iblkit-view") + " " + arguments);
  std::ifstream stream(dir / "log");
  for (std::string line; std::getline(stream, line);) {
    result.log += line + "\n";
    const std::string wrote = "iblkit-view: wrote ", separator = " and ";
    if (line.rfind(wrote, 0) != 0) continue;
    const std::size_t at = line.find(separator);
    result.shots.push_back({line.substr(wrote.size(), at - wrote.size()), line.substr(at + separator.size())});
  }
  return result;
}

double meanAbsoluteDifference(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const glm::vec4 d = glm::abs(a.pixels()[i] - b.pixels()[i]);
    sum += (d.r + d.g + d.b) / 3.0;
  }
  return sum / double(a.pixels().size());
}

int coveredPixels(const Image& radiance) {
  int covered = 0;
  for (const glm::vec4& p : radiance.pixels()) covered += p.a == 1.0f;
  return covered;
}

class IblkitViewWindowEvents : public IblkitViewWindow {
 protected:
  void SetUp() override {
    IblkitViewWindow::SetUp();
    if (IsSkipped()) return;
    ASSERT_EQ(run("command -v xdotool >/dev/null").status, 0) << "xdotool is missing: install it (scripts/setup.sh)";
  }
};

// Real input events: a left drag orbits, the wheel zooms, a key switches the mode, the window
// resized by the X server gives frames (and screenshots) of its new size, a right drag pans.
TEST_F(IblkitViewWindowEvents, DragWheelKeyAndResizeChangeTheFrameAsTheyShould) {
  const DrivenRun r = drive(dir_,
                            "mousemove --window %W 80 60\nkey p\nshots 1\n"
                            "mousedown 1\nmousemove --window %W 120 60\nmouseup 1\nkey p\nshots 2\n"
                            "click --repeat 3 4\nkey p\nshots 3\n"
                            "key 1\nkey p\nshots 4\n"
                            "windowsize %W 200 150\nkey p\nshots 5\n"
                            "mousedown 3\nmousemove --window %W 150 75\nmouseup 3\nkey p\nshots 6\n",
                            windowArguments("--no-panel"));
  ASSERT_EQ(r.run.status, 0) << r.run.output << r.log;
  ASSERT_EQ(r.shots.size(), 6u) << r.log;
  std::vector<Image> radiance, shown;
  for (const Shot& shot : r.shots) {
    radiance.push_back(readExr(shot.exr));
    shown.push_back(readPng(shot.png));
  }
  for (int i = 0; i < 4; ++i) {
    ASSERT_EQ(shown[std::size_t(i)].width(), kWidth) << i;
    ASSERT_EQ(shown[std::size_t(i)].height(), kHeight) << i;
  }
  // The first is the scene's camera: the headless frame.
  EXPECT_LT(meanAbsoluteDifference(radiance[0], renderHeadless("start.exr")), 1e-3);
  // A 40-pixel drag turns the view by a quarter of pi: the sky behind the sphere moves.
  EXPECT_GT(meanAbsoluteDifference(shown[0], shown[1]), 0.02);
  // Three wheel steps towards the sphere (x0.9 each): it covers more of the frame.
  EXPECT_GT(coveredPixels(radiance[2]), coveredPixels(radiance[1]) * 13 / 10)
      << coveredPixels(radiance[1]) << " -> " << coveredPixels(radiance[2]);
  // Key 1, the unlit mode: the mirror shows its flat base colour instead of the sky.
  EXPECT_GT(meanAbsoluteDifference(shown[2], shown[3]), 0.05);
  EXPECT_EQ(coveredPixels(radiance[3]), coveredPixels(radiance[2]));
  // Resized to 200 x 150: both files have the new size, the same view at the same scale (the
  // vertical field of view kept; the same shape, so the sphere covers the same fraction).
  EXPECT_EQ(radiance[4].width(), 200);
  EXPECT_EQ(radiance[4].height(), 150);
  EXPECT_EQ(shown[4].width(), 200);
  EXPECT_EQ(shown[4].height(), 150);
  const double before = double(coveredPixels(radiance[3])) / double(kWidth * kHeight);
  const double after = double(coveredPixels(radiance[4])) / (200.0 * 150.0);
  EXPECT_NEAR(after, before, 0.02);
  // A right drag pans: the sphere follows the cursor, 50 pixels to the right, its coverage about kept.
  auto centreX = [](const Image& frame) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < frame.height(); ++y)
      for (int x = 0; x < frame.width(); ++x)
        if (frame.at(x, y).a == 1.0f) sum += x, ++count;
    return count > 0 ? sum / count : 0.0;
  };
  EXPECT_GT(centreX(radiance[5]), centreX(radiance[4]) + 10.0) << centreX(radiance[4]) << " -> " << centreX(radiance[5]);
}

// A window wider than the reference: the image keeps the live frame's scale (full height,
// centred, black beside it), and the difference view compares each pixel with the live pixel
// under it, so the headless frame of the narrower shape is black against the wider live frame.
TEST_F(IblkitViewWindow, AReferenceKeepsTheLiveFramesScaleInAWiderWindow) {
  const fs::path magenta = dir_ / "magenta.exr";
  writeExr(magenta, Image(kWidth, kHeight, glm::vec4(2.0f, 0.0f, 2.0f, 1.0f)), {.pixelType = PixelType::Float});
  const std::string wide = " --width 240 --height 120 --env-dir " + shellQuoted(dir_ / "no-maps");
  const fs::path imageShot = dir_ / "wide-image.png";
  ProgramRun r = run(inWindow(shellQuoted(bake_) + wide + " --reference " + shellQuoted(magenta) +
                              " --compare image --frames 2 --screenshot " + shellQuoted(imageShot)));
  ASSERT_EQ(r.status, 0) << r.output;
  const Image image = readPng(imageShot);
  ASSERT_EQ(image.width(), 240);
  int inside = 0, outside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < 240; ++x) {
      if (x >= 40 && x < 200) inside += isMagenta(image.at(x, y));
      else outside += maxComponent(image.at(x, y)) == 0.0f;
    }
  EXPECT_EQ(inside, kWidth * kHeight);
  EXPECT_EQ(outside, 80 * kHeight);

  renderHeadless("narrow.exr");
  const fs::path differenceShot = dir_ / "wide-difference.png";
  r = run(inWindow(shellQuoted(bake_) + wide + " --reference " + shellQuoted(dir_ / "narrow.exr") +
                   " --compare difference --frames 2 --screenshot " + shellQuoted(differenceShot)));
  ASSERT_EQ(r.status, 0) << r.output;
  const Image difference = readPng(differenceShot);
  int black = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 40; x < 200; ++x) black += maxComponent(difference.at(x, y)) < 0.02f;
  EXPECT_GT(black, kWidth * kHeight * 97 / 100);
}

// A real iblkit-report output (the mirror sphere under sky, two modes, 160x90, an 8-spp
// reference: about 9 s): its case's images are the scene at the window's camera, so the
// difference view of each against the live frame of the same bake is dark nearly everywhere.
TEST_F(IblkitViewWindow, ARealReportCaseLinesUpWithTheLiveFrame) {
  const fs::path report = dir_ / "report";
  ProgramRun r = run(program("iblkit-report") + " --bin " + shellQuoted(test::binDir()) + " " +
                     shellQuoted(test::assetsDir() / "scenes" / "mirror_sphere.json") + " --env-dir " +
                     shellQuoted(test::assetsDir() / "hdri") +
                     " --envs sky --modes mirror,full --width 160 --height 90 --pass-spp 4 --min-passes 2"
                     " --max-passes 2 --bench 1 -o " + shellQuoted(report));
  ASSERT_EQ(r.status, 0) << r.output;
  // The images in the report's order, as a bad --show lists them.
  r = run(program("iblkit-view") + " " + shellQuoted(bake_) + " --reference " + shellQuoted(report) + " --show none");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("case mirror_sphere-sky (expected one of reference, mirror, full)"), std::string::npos)
      << r.output;
  for (const char* shown : {"reference", "mirror", "full"}) {
    const fs::path shot = dir_ / (std::string("difference-") + shown + ".png");
    r = run(inWindow(shellQuoted(bake_) + " --env-dir " + shellQuoted(dir_ / "no-maps") + " --reference " +
                     shellQuoted(report) + " --case mirror_sphere-sky --compare difference --show " + shown +
                     " --frames 2 --screenshot " + shellQuoted(shot)));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("2 frames, 160x90"), std::string::npos) << r.output;  // the report's size
    const Image difference = readPng(shot);
    int dark = 0;
    for (const glm::vec4& p : difference.pixels()) dark += maxComponent(p) < 0.1f;
    EXPECT_GT(dark, int(difference.pixelCount()) * 95 / 100) << shown;  // measured: 98.8%
  }
  // Without a MODEL the case opens its own scene (mirror_sphere.json, baked in memory) under its
  // own map (sky), so the live frame lines up with the reference just the same.
  const fs::path own = dir_ / "own-scene.png";
  r = run(inWindow("--env-dir " + shellQuoted(dir_ / "no-maps") + " --reference " + shellQuoted(report) +
                   " --case mirror_sphere-sky --compare difference --show reference --frames 2 --screenshot " +
                   shellQuoted(own)));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 frames, 160x90"), std::string::npos) << r.output;
  const Image difference = readPng(own);
  int dark = 0;
  for (const glm::vec4& p : difference.pixels()) dark += maxComponent(p) < 0.1f;
  EXPECT_GT(dark, int(difference.pixelCount()) * 95 / 100);
  // Under another map (--env) the same case's reference no longer lines up.
  const fs::path other = dir_ / "own-scene-studio.png";
  r = run(inWindow("--env " + shellQuoted(test::assetsDir() / "hdri" / "studio.exr") + " --env-dir " +
                   shellQuoted(dir_ / "no-maps") + " --reference " + shellQuoted(report) +
                   " --compare difference --show reference --frames 2 --screenshot " + shellQuoted(other)));
  ASSERT_EQ(r.status, 0) << r.output;
  const Image otherDifference = readPng(other);
  int otherDark = 0;
  for (const glm::vec4& p : otherDifference.pixels()) otherDark += maxComponent(p) < 0.1f;
  EXPECT_LT(otherDark, int(otherDifference.pixelCount()) * 90 / 100);
  // Headless, or with no report, a MODEL is still required.
  r = run(program("iblkit-view") + " --headless -o " + shellQuoted(dir_ / "x.exr"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "iblkit-view: input is required\n");
  r = run(program("iblkit-view") + " --reference " + shellQuoted(dir_ / "x.exr"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "iblkit-view: input is required\n");
}

// A high-DPI X screen, as a desktop sets one: Xft.dpi 192 in the server's resources (xrdb), which
// GLFW reads as a content scale of 2. The framebuffer stays the window's size on X11, so the panel
// is scaled 2x (panelScale); at the default 96 dpi it is not scaled. The frame is the window's size.
TEST_F(IblkitViewWindow, AHighDpiScreenScalesThePanelAndNotTheFrame) {
  ASSERT_EQ(run("command -v xrdb >/dev/null").status, 0) << "xrdb is missing: install x11-xserver-utils (scripts/setup.sh)";
  const fs::path shot = dir_ / "high-dpi.png";
  // The inner command in double quotes: its paths are single-quoted (shellQuoted). -noreset: Xvfb
  // would otherwise reset, and forget the resources, when xrdb disconnects as its last client.
  ProgramRun r = run("xvfb-run -a -s '-screen 0 640x480x24 -noreset' sh -c \"echo 'Xft.dpi: 192' | xrdb -nocpp -merge && exec " +
                     program("iblkit-view") + " " + windowArguments("--frames 2 --screenshot " + shellQuoted(shot)) + "\"");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("iblkit-view: panel scaled 2x (content scale 2, window " + std::to_string(kWidth) +
                          " px wide, framebuffer " + std::to_string(kWidth) + ")"),
            std::string::npos)
      << r.output;
  const Image frame = readPng(shot);
  EXPECT_EQ(frame.width(), kWidth);
  EXPECT_EQ(frame.height(), kHeight);
  r = run(inWindow(windowArguments("--frames 2")));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("panel scaled"), std::string::npos) << r.output;
}

// A report case: the reference and each mode's frame, written by the report's writers.
class IblkitViewReportCase : public IblkitViewWindow {
 protected:
  void SetUp() override {
    IblkitViewWindow::SetUp();
    if (IsSkipped()) return;
    report_ = dir_ / "report";
    test::writeReportOutput(report_, {{"mirror_sphere", "sky",
                                       {{"reference", Image(kWidth, kHeight, glm::vec4(2.0f, 0.0f, 2.0f, 1.0f))},
                                        {"full", Image(kWidth, kHeight, glm::vec4(0.0f, 2.0f, 0.0f, 1.0f))},
                                        {"mirror", Image(kWidth, kHeight, glm::vec4(0.0f, 0.0f, 2.0f, 1.0f))}}}});
  }

  // The colour that fills a screenshot ('m'agenta, 'g'reen, 'b'lue; '?' for anything else).
  static char fill(const Image& png) {
    int magenta = 0, green = 0, blue = 0;
    for (const glm::vec4& p : png.pixels()) {
      magenta += p.r > 0.3f && p.b > 0.3f && p.g < 0.01f;
      green += p.g > 0.3f && p.r < 0.01f && p.b < 0.01f;
      blue += p.b > 0.3f && p.r < 0.01f && p.g < 0.01f;
    }
    const int all = int(png.pixelCount());
    return magenta == all ? 'm' : green == all ? 'g' : blue == all ? 'b' : '?';
  }

  fs::path report_;
};

TEST_F(IblkitViewReportCase, ShowStartsAtTheNamedImageAndBadCasesAreOneLine) {
  const fs::path shot = dir_ / "full.png";
  ProgramRun r = run(inWindow(windowArguments("--reference " + shellQuoted(report_) +
                                              " --case mirror_sphere-sky --show full --compare image --frames 2 "
                                              "--screenshot " + shellQuoted(shot))));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(fill(readPng(shot)), 'g');
  // report.json itself, the only case taken without --case, the split view: live left, the reference right.
  const fs::path split = dir_ / "split.png";
  r = run(inWindow(windowArguments("--reference " + shellQuoted(report_ / "report.json") + " --frames 2 --screenshot " +
                                   shellQuoted(split))));
  ASSERT_EQ(r.status, 0) << r.output;
  const Image splitShown = readPng(split);
  EXPECT_TRUE(isMagenta(splitShown.at(kWidth - 1, kHeight / 2)));
  EXPECT_FALSE(isMagenta(splitShown.at(0, kHeight / 2)));

  const std::string json = (report_ / "report.json").string();
  r = run(program("iblkit-view") + " " + windowArguments("--reference " + shellQuoted(report_) + " --case bunny-sky"));
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(r.output.ends_with("iblkit-view: " + json + ": no case 'bunny-sky' (cases: mirror_sphere-sky)\n")) << r.output;
  r = run(program("iblkit-view") + " " + windowArguments("--reference " + shellQuoted(dir_ / "no-report") + "/"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("iblkit-view: " + (dir_ / "no-report").string() + "/: cannot open"), std::string::npos)
      << r.output;
  fs::remove(report_ / "images" / "mirror_sphere-sky-linear.js");
  r = run(program("iblkit-view") + " " + windowArguments("--reference " + shellQuoted(report_)));
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(r.output.ends_with("iblkit-view: " + (report_ / "images" / "mirror_sphere-sky-linear.js").string() +
                                 ": cannot open: No such file or directory\n"))
      << r.output;
  r = run(program("iblkit-view") + " " + windowArguments("--reference " + shellQuoted(report_) + " --show sh"));
  EXPECT_EQ(r.status, 1);  // the missing images script comes first
  r = run(program("iblkit-view") + " " + windowArguments("--case mirror_sphere-sky"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "iblkit-view: --case: only with --reference REPORT\n");
}

TEST_F(IblkitViewReportCase, BracesFlipThroughTheReferenceAndTheModesAndTheTitleSaysWhich) {
  const DrivenRun r = drive(dir_,
                            "key p\nshots 1\n"
                            "key shift+bracketright\nkey p\nshots 2\n"
                            "key shift+bracketright\nkey p\nshots 3\ngetwindowname %W\n"
                            "key shift+bracketright\nkey shift+bracketleft\nkey p\nshots 4\n",
                            windowArguments("--no-panel --compare image --reference " + shellQuoted(report_) +
                                            " --case mirror_sphere-sky"));
  ASSERT_EQ(r.run.status, 0) << r.run.output << r.log;
  ASSERT_EQ(r.shots.size(), 4u) << r.log;
  std::string fills;
  for (const Shot& shot : r.shots) fills += fill(readPng(shot.png));
  EXPECT_EQ(fills, "mgbb");
  EXPECT_NE(r.log.find("iblkit-view: showing full (2 of 3)\n"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("iblkit-view: showing reference (1 of 3)\n"), std::string::npos) << r.log;
  EXPECT_NE(r.run.output.find("iblkit-view: bake | image: mirror (3 of 3)"), std::string::npos) << r.run.output;
  // --show with a name the case does not have: a usage error listing the names.
  const ProgramRun bad = run(program("iblkit-view") + " " +
                             windowArguments("--reference " + shellQuoted(report_) + " --show sh"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(bad.output.ends_with("iblkit-view: --show: no image 'sh' in " + (report_ / "report.json").string() +
                                   ", case mirror_sphere-sky (expected one of reference, full, mirror)\n"))
      << bad.output;
}

}  // namespace
}  // namespace iblkit
