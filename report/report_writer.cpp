#include "report/report_writer.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/file_io.h"
#include "report/compare_view.h"
#include "report/cost_plot.h"
#include "report/html_text.h"
#include "report/label_layout.h"
#include "report/svg_plot.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void writeText(const fs::path& file, const std::string& text) {
  writeAtomically(file, [&](const fs::path& temporary) {
    std::ofstream stream(temporary, std::ios::binary);
    stream << text;
    if (!stream.flush()) fail(file, "cannot write file");
  });
}

json number(double value) { return std::isfinite(value) ? json(value) : json(); }

std::string fixed(double value, int digits) { return fixedText(value, digits); }
std::string escape(const std::string& text) { return escapeHtml(text); }

std::vector<std::string> scenesInOrder(const std::vector<CaseResult>& cases) {
  std::vector<std::string> scenes;
  for (const CaseResult& result : cases)
    if (std::find(scenes.begin(), scenes.end(), result.scene) == scenes.end()) scenes.push_back(result.scene);
  return scenes;
}

const ModeResult* findMode(const CaseResult& result, const std::string& mode) {
  for (const ModeResult& modeResult : result.modes)
    if (modeResult.mode == mode) return &modeResult;
  return nullptr;
}

std::string kindName(const CaseResult& result) {
  return result.mapKind ? std::string(mapKindName(*result.mapKind)) : std::string();
}

// The scene's cases under maps of `kind`.
std::vector<const CaseResult*> casesOfKind(const std::vector<const CaseResult*>& sceneCases, MapKind kind) {
  std::vector<const CaseResult*> selected;
  for (const CaseResult* result : sceneCases)
    if (result->mapKind == kind) selected.push_back(result);
  return selected;
}

// The mean FLIP of `mode` over `cases`; NaN when one of them failed or none scored it.
double meanFlip(const std::vector<const CaseResult*>& cases, const std::string& mode) {
  double sum = 0.0;
  int count = 0;
  for (const CaseResult* result : cases) {
    const ModeResult* modeResult = findMode(*result, mode);
    if (!modeResult) continue;
    if (!modeResult->failure.empty()) return std::numeric_limits<double>::quiet_NaN();
    sum += modeResult->scores.meanFlip;
    ++count;
  }
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

// One table per report: for each scene, every mode's mean FLIP averaged over the maps of each
// kind, so that the diffuse terms (SH9, the irradiance cube) and the dominant lights stand side
// by side per kind of lighting.
std::string kindTable(const ReportSummary& summary, const std::vector<std::string>& scenes) {
  std::vector<MapKind> kinds;
  for (const auto& [kind, name] : kMapKindNames)
    if (std::any_of(summary.cases.begin(), summary.cases.end(),
                    [&](const CaseResult& result) { return result.mapKind == kind; }))
      kinds.push_back(kind);
  if (kinds.empty()) return {};
  std::ostringstream html;
  html << "<h2>By kind of map</h2>\n<p class=small>Mean FLIP of each mode averaged over the maps of each kind "
          "(docs/report.md \"Kinds of map\": sunny, a sun holding a large share of the map's energy; studio, a few "
          "bright sources a few degrees wide; soft, neither).</p>\n<table><tr><th class=l>scene</th><th class=l>mode</th>";
  for (const MapKind kind : kinds) {
    std::vector<std::string> names;
    for (const CaseResult& result : summary.cases)
      if (result.mapKind == kind && std::find(names.begin(), names.end(), result.environment) == names.end())
        names.push_back(result.environment);
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    html << "<th>" << mapKindName(kind) << "<br><span class=small>" << escape(list) << "</span></th>";
  }
  html << "</tr>\n";
  for (const std::string& scene : scenes) {
    std::vector<const CaseResult*> sceneCases;
    for (const CaseResult& result : summary.cases)
      if (result.scene == scene) sceneCases.push_back(&result);
    for (const std::string& mode : summary.modes) {
      if (std::none_of(sceneCases.begin(), sceneCases.end(),
                       [&](const CaseResult* result) { return findMode(*result, mode) != nullptr; }))
        continue;
      html << "<tr><td class=l>" << scene << "</td><td class=l>" << mode << "</td>";
      for (const MapKind kind : kinds) html << "<td>" << fixed(meanFlip(casesOfKind(sceneCases, kind), mode), 4) << "</td>";
      html << "</tr>\n";
    }
  }
  html << "</table>\n";
  return html.str();
}

// The summary: every scene's mean FLIP per mode averaged over its maps, the closest mode of each
// scene in bold, a mode that does not apply to the scene marked so (case_modes.h).
std::string summaryTable(const ReportSummary& summary, const std::vector<std::string>& scenes) {
  std::ostringstream html;
  html << "<h2>Summary</h2>\n<p class=small>Mean FLIP of each mode averaged over the scene's maps (lower is closer "
          "to the path-traced reference); bold: the scene's closest mode; n/a: the mode does not apply to the "
          "scene's materials and is not scored (hover for why). Per-case pictures: open a case below.</p>\n"
          "<table><tr><th class=l>scene</th>";
  for (const std::string& mode : summary.modes) html << "<th>" << mode << "</th>";
  html << "</tr>\n";
  for (const std::string& scene : scenes) {
    std::vector<double> means;
    double best = std::numeric_limits<double>::infinity();
    for (const std::string& mode : summary.modes) {
      means.push_back(meanOverEnvironments(summary.cases, scene, mode, Metric::MeanFlip));
      if (std::isfinite(means.back())) best = std::min(best, means.back());
    }
    html << "<tr><td class=l><a href=\"#scene-" << scene << "\">" << scene << "</a></td>";
    for (std::size_t m = 0; m < summary.modes.size(); ++m) {
      std::string why;
      for (const CaseResult& result : summary.cases)
        if (result.scene == scene)
          for (const auto& [mode, reason] : result.notApplicable)
            if (mode == summary.modes[m]) why = reason;
      if (!std::isfinite(means[m]) && !why.empty())
        html << "<td class=na title=\"" << escape(why) << "\">n/a</td>";
      else
        html << "<td" << (means[m] == best ? " class=best" : "") << ">" << fixed(means[m], 4) << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</table>\n";
  return html.str();
}

// The requested modes a scene does not score, grouped by why.
std::string notApplicableNote(const std::vector<const CaseResult*>& sceneCases) {
  std::vector<std::pair<std::string, std::vector<std::string>>> byReason;  // why, the modes
  for (const CaseResult* result : sceneCases)
    for (const auto& [mode, why] : result->notApplicable) {
      auto group = std::find_if(byReason.begin(), byReason.end(), [&](const auto& entry) { return entry.first == why; });
      if (group == byReason.end()) group = byReason.insert(byReason.end(), {why, {}});
      if (std::find(group->second.begin(), group->second.end(), mode) == group->second.end()) group->second.push_back(mode);
    }
  if (byReason.empty()) return {};
  std::string note = "<p class=small>Not scored here (the modes that apply come from the scene's materials, "
                     "docs/report.md): ";
  for (std::size_t i = 0; i < byReason.size(); ++i) {
    note += i ? "; " : "";
    for (std::size_t m = 0; m < byReason[i].second.size(); ++m)
      note += (m ? ", " : "") + std::string("<code>") + byReason[i].second[m] + "</code>";
    note += " (" + escape(byReason[i].first) + ")";
  }
  return note + ".</p>\n";
}

}  // namespace

void writeReportJson(const fs::path& file, const ReportSummary& summary) {
  json document;
  document["settings"] = {{"width", summary.settings.width},
                          {"height", summary.settings.height},
                          {"modes", summary.modes},
                          {"passSpp", summary.settings.passSpp},
                          {"engineSamples", summary.settings.engineSamples},
                          {"engineSupersample", summary.settings.engineSupersample},
                          {"referenceIntegrator", summary.settings.referenceIntegrator},
                          {"maxPasses", summary.settings.maxPasses},
                          {"negligibleRatio", summary.settings.negligibleRatio},
                          {"negligibleRelMse", summary.settings.negligibleRelMse},
                          {"maxReferenceRelMse", summary.settings.maxReferenceRelMse},
                          {"referenceLightSamples", summary.settings.referenceLightSamples}};
  document["seconds"] = summary.totalSeconds;
  document["stages"] = {{"cached", summary.cachedStages}, {"run", summary.runStages}};
  for (const Claim& claim : summary.claims)
    document["claims"].push_back({{"statement", claim.statement},
                                  {"measured", number(claim.measured)},
                                  {"bound", number(claim.bound)},
                                  {"holds", claim.holds},
                                  {"detail", claim.detail}});
  for (const CaseResult& result : summary.cases) {
    json entry = {{"scene", result.scene},
                  {"environment", result.environment},
                  {"sceneFile", result.sceneFile.string()},
                  {"environmentFile", result.environmentFile.string()},
                  {"mapKind", result.mapKind ? json(kindName(result)) : json()},
                  {"mapSunShare", number(result.concentration.sunShare)},
                  {"mapSourceShare", number(result.concentration.sourceShare)},
                  {"bakeSeconds", result.bakeSeconds},
                  {"visibilitySeconds", result.visibilitySeconds},
                  {"environmentSeconds", result.environmentSeconds},
                  {"traceSeconds", result.traceSeconds},
                  {"reference", {{"spp", result.referenceSpp},
                                 {"relMseEstimate", number(result.referenceRelMse)},
                                 {"halvesMeanFlip", number(result.referenceHalvesFlip)},
                                 {"converged", result.referenceConverged},
                                 {"image", result.referenceImage}}},
                  {"scoredPixels", result.scoredPixels},
                  {"sh9TruncationError", number(result.sh9Truncation)},
                  {"shErrorBeyondSh9", number(result.shBeyondSh9)},
                  {"flipExposureRange", {result.flipExposures.start, result.flipExposures.stop}},
                  {"thumbnailExposure", result.exposure},
                  {"commands", result.commands}};
    for (const auto& [mode, why] : result.notApplicable) entry["notApplicable"].push_back({{"mode", mode}, {"why", why}});
    if (!result.linearImages.empty()) entry["linearImages"] = result.linearImages;
    for (const ModeResult& modeResult : result.modes) {
      json mode = {{"mode", modeResult.mode}, {"frameMilliseconds", number(modeResult.frameMilliseconds)}};
      if (modeResult.failure.empty()) {
        mode["meanFlip"] = modeResult.scores.meanFlip;
        mode["relMse"] = modeResult.scores.relMse;
        mode["meanRelativeError"] = modeResult.scores.meanRelativeError;
        mode["ssim"] = modeResult.scores.ssim;
        mode["image"] = modeResult.image;
        mode["flipHeatMap"] = modeResult.heatMap;
      } else {
        mode["failure"] = modeResult.failure;
      }
      entry["modes"].push_back(mode);
    }
    document["cases"].push_back(entry);
  }
  writeText(file, document.dump(2) + "\n");
}

std::string ladderSvg(const std::vector<CaseResult>& cases, const std::string& scene,
                      const std::vector<std::string>& modes) {
  constexpr double kWidth = 560, kHeight = 300, kLeft = 60, kRight = 110, kTop = 16, kBottom = 84, kFont = 11;
  constexpr SvgPlotFrame kFrame{kWidth, kHeight, kLeft, kRight, kTop, kBottom, kFont};
  double top = 0.0;
  std::vector<const CaseResult*> sceneCases;
  for (const CaseResult& result : cases) {
    if (result.scene != scene) continue;
    sceneCases.push_back(&result);
    for (const ModeResult& modeResult : result.modes)
      if (modeResult.failure.empty()) top = std::max(top, modeResult.scores.meanFlip);
  }
  top = top > 0.0 ? top * 1.1 : 1.0;
  const double plotWidth = kFrame.plotWidth(), plotHeight = kFrame.plotHeight();
  auto x = [&](std::size_t i) { return kLeft + (modes.size() > 1 ? plotWidth * double(i) / double(modes.size() - 1) : 0.0); };
  auto y = [&](double value) { return kFrame.y(value, top); };

  std::ostringstream svg;
  svg.setf(std::ios::fixed);
  svg.precision(1);
  beginSvgPlot(svg, "ladder", kFrame, top);
  svg << "<text x=\"14\" y=\"" << kTop + plotHeight / 2 << "\" transform=\"rotate(-90 14 " << kTop + plotHeight / 2
      << ")\" text-anchor=\"middle\">mean FLIP</text>\n";
  // The modes' names turned by 40 degrees: neighbours at least plotWidth / 9 apart then clear
  // each other by that times sin(40 degrees), more than the font's height.
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const double tx = x(i) + 3, ty = kTop + plotHeight + 12;
    svg << "<text class=mode x=\"" << tx << "\" y=\"" << ty << "\" text-anchor=\"end\" transform=\"rotate(-40 " << tx
        << " " << ty << ")\">" << modes[i] << "</text>\n";
  }

  // The lines first, their labels after, placed together so that none overlaps (label_layout.h).
  std::vector<LabelBox> wanted;
  std::vector<std::string> labels;
  auto polyline = [&](const std::vector<double>& values, const char* style, const std::string& label,
                      const std::string& text) {
    std::ostringstream points;
    points.setf(std::ios::fixed);
    points.precision(1);
    double lastY = kTop + plotHeight;
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i])) continue;
      points << x(i) << "," << y(values[i]) << " ";
      lastY = y(values[i]);
    }
    svg << "<polyline fill=\"none\" " << style << " points=\"" << points.str() << "\"/>\n";
    wanted.push_back({kLeft + plotWidth + 6, lastY - kFont / 2 - 1, labelWidth(text, kFont), kFont + 2});
    labels.push_back(label);
  };
  for (const CaseResult* result : sceneCases) {
    std::vector<double> values;
    for (const std::string& mode : modes) {
      const ModeResult* modeResult = findMode(*result, mode);
      values.push_back(modeResult && modeResult->failure.empty() ? modeResult->scores.meanFlip
                                                                  : std::numeric_limits<double>::quiet_NaN());
    }
    polyline(values, "stroke=\"#9ab\" stroke-width=\"1\"", result->environment, result->environment);
  }
  std::vector<double> means;
  for (const std::string& mode : modes) means.push_back(meanOverEnvironments(cases, scene, mode, Metric::MeanFlip));
  polyline(means, "stroke=\"#c30\" stroke-width=\"3\"", "<tspan font-weight=\"bold\">mean</tspan>", "mean");
  const std::vector<double> labelY = placeLabels(wanted, kTop - 8, kTop + plotHeight + 8);
  for (std::size_t i = 0; i < labels.size(); ++i)
    svg << "<text class=label x=\"" << wanted[i].x << "\" y=\"" << labelY[i] + kFont << "\">" << labels[i] << "</text>\n";
  svg << "</svg>\n";
  return svg.str();
}

void writeReportHtml(const fs::path& file, const ReportSummary& summary) {
  std::ostringstream html;
  html << R"(<!doctype html>
<html><head><meta charset="utf-8"><title>iblkit: real-time IBL approximations against the path-traced truth</title>
<style>
body{font-family:sans-serif;margin:2em;max-width:1500px;color:#222}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:3px 6px;font-size:13px;text-align:right}
th{background:#f4f4f4}td.l,th.l{text-align:left}.ok{color:#070;font-weight:bold}.no{color:#b00;font-weight:bold}
figure{display:inline-block;margin:2px;vertical-align:top}figcaption{font-size:11px;text-align:center}
img{display:block}code{font-size:11px}.small{font-size:12px;color:#555}
.plots{display:flex;flex-wrap:wrap;gap:1em;align-items:flex-start}.plots>div{max-width:580px}details.case{margin:.3em 0}
details.case>summary{cursor:pointer;font-weight:bold;font-size:14px}td.na{color:#999}td.best{font-weight:bold}
)" << compareViewStyle() << R"(
</style></head><body>
<h1>iblkit: how far each real-time approximation is from the path-traced truth</h1>
<p>Every scene is baked (<code>iblkit-bake</code>), rendered headless in every engine mode
(<code>iblkit-view</code>, OpenGL) and path-traced (<code>iblkit-trace</code>) with the same camera,
environment orientation, material model and tone curve. Each mode is scored against the reference
over the pixels that see geometry (the sky is trivially right): HDR-FLIP with one exposure bracket
per reference, relative MSE, the luminance-weighted mean relative error and SSIM
(<code>docs/scoring.md</code>, <code>docs/report.md</code>). The reference is traced in passes until its own
relMSE, estimated from two independent halves, is at most )"
       << summary.settings.maxReferenceRelMse << R"( and at most )" << summary.settings.negligibleRatio * 100.0
       << R"(% of the best mode's or )" << summary.settings.negligibleRelMse
       << R"( (1% RMS noise), whichever is larger; the halves' FLIP against each other shows how visible that noise is.</p>
)";
  std::error_code error;
  if (fs::exists(file.parent_path() / "inputs.html", error))
    html << "<p>The inputs (every map, model and scene, checked): <a href=\"inputs.html\">inputs.html</a>.</p>\n";
  html << "<h2>What the numbers must show</h2>\n<table><tr><th class=l>claim</th><th>measured</th><th>bound</th><th>holds</th><th class=l>detail</th></tr>\n";
  for (const Claim& claim : summary.claims)
    html << "<tr><td class=l>" << escape(claim.statement) << "</td><td>" << fixed(claim.measured, 4) << "</td><td>"
         << fixed(claim.bound, 4) << "</td><td class=" << (claim.holds ? "ok>yes" : "no>no") << "</td><td class=l>"
         << escape(claim.detail) << "</td></tr>\n";
  html << "</table>\n";
  if (std::any_of(summary.claims.begin(), summary.claims.end(), [](const Claim& claim) {
        return !claim.holds && claim.statement.find(std::string(": ") + kLightClaimMode + " mean FLIP") != std::string::npos;
      }))
    html << "<p class=why><b>Where the dominant lights lose to <code>" << kLightBaselineMode << "</code>:</b> compare the <code>"
         << kLightClaimMode << "</code> heat maps with <code>" << kLightBaselineMode
         << "</code>'s below. docs/report.md (\"The dominant lights measured\") says what they showed when these claims "
            "were first measured: the suns' light bounced off the ground is missing on the bunny, the residual is shaded "
            "without the PRT transfer where no sun is extracted, and the shadow map darkens the lone sphere's lit side "
            "near the terminator.</p>\n";
  for (const Claim& claim : summary.claims) {
    if (claim.holds) continue;
    if (claim.statement.rfind("diffuse_sphere: sh mode mean relative error", 0) == 0)
      html << "<p class=why><b>Why the diffuse sphere's 3% does not hold:</b> that is the error of SH9 itself. "
              "Nine coefficients cannot hold the irradiance of a map with a sun or small bright lights; "
              "the column <i>SH9's own error</i> below gives it per map, computed by brute force on the same "
              "normals, and <i>sh beyond SH9</i> what the engine adds to it (docs/report.md).</p>\n";
    if (claim.statement.rfind("bunny: mean FLIP of sh > sh-ao", 0) == 0)
      html << "<p class=why><b>Why AO does not help here:</b> the bunny and its ground are white (albedo 0.8). "
              "The directions AO takes away are mostly the ground's, which in the path-traced reference send back "
              "light bounced off the lit ground; and a scalar AO dims every direction alike, the bright sky above "
              "included, while what the ground blocks is the darker lower half of the map. The bent normal and "
              "PRT take the blocked directions into account, and <code>full</code>'s multi-bounce AO puts the "
              "bounced light back. Against a reference without interreflection (<code>--integrator direct</code>) "
              "AO lowers the relMSE that <code>sh</code> has in the shadows, but not the FLIP of the lit areas "
              "(docs/report.md).</p>\n";
  }

  html << summaryTable(summary, scenesInOrder(summary.cases)) << kindTable(summary, scenesInOrder(summary.cases));
  for (const std::string& scene : scenesInOrder(summary.cases)) {
    html << "<h2 id=\"scene-" << scene << "\">" << scene << "</h2>\n";
    std::vector<const CaseResult*> sceneCases;
    for (const CaseResult& result : summary.cases)
      if (result.scene == scene) sceneCases.push_back(&result);
    html << "<p class=small>Mean FLIP / relMSE / mean relative error per mode and environment; the last column"
            " averages over the environments.</p>\n<table><tr><th class=l>mode</th>";
    for (const CaseResult* result : sceneCases)
      html << "<th>" << result->environment << "<br><span class=small>" << kindName(*result) << "</span></th>";
    html << "<th>mean</th><th>frame (ms)</th></tr>\n";
    // The modes some case of this scene scored: those that apply to its materials (case_modes.h).
    std::vector<std::string> sceneModes;
    for (const std::string& mode : summary.modes)
      if (std::any_of(sceneCases.begin(), sceneCases.end(),
                      [&](const CaseResult* result) { return findMode(*result, mode) != nullptr; }))
        sceneModes.push_back(mode);
    for (const std::string& mode : sceneModes) {
      html << "<tr><td class=l>" << mode << "</td>";
      for (const CaseResult* result : sceneCases) {
        const ModeResult* modeResult = findMode(*result, mode);
        if (!modeResult) {
          html << "<td></td>";
        } else if (!modeResult->failure.empty()) {
          html << "<td class=no title=\"" << escape(modeResult->failure) << "\">failed</td>";
        } else {
          html << "<td>" << fixed(modeResult->scores.meanFlip, 4) << " / " << fixed(modeResult->scores.relMse, 4)
               << " / " << fixed(100.0 * modeResult->scores.meanRelativeError, 1) << "%</td>";
        }
      }
      html << "<td><b>" << fixed(meanOverEnvironments(summary.cases, scene, mode, Metric::MeanFlip), 4) << " / "
           << fixed(meanOverEnvironments(summary.cases, scene, mode, Metric::RelMse), 4) << " / "
           << fixed(100.0 * meanOverEnvironments(summary.cases, scene, mode, Metric::MeanRelativeError), 1)
           << "%</b></td><td>" << fixed(sceneFrameMilliseconds(summary.cases, scene, mode), 1)
           << "</td></tr>\n";
    }
    html << "</table>\n" << notApplicableNote(sceneCases);
    html << "<div class=plots><div><div class=small>The ladder: mean FLIP per mode, one line per map</div>"
         << ladderSvg(summary.cases, scene, sceneModes)
         << "</div><div><div class=small>Cost against error: median frame time against mean FLIP; filled and joined, "
            "the Pareto front (no other mode both faster and closer)</div>"
         << costSvg(costPoints(summary.cases, scene, sceneModes)) << "</div></div>\n";
    html << "<table><tr><th class=l>environment</th>"
            "<th title=\"the map's kind (docs/report.md): energy share of its brightest 1e-4 and 1% of the sphere\">"
            "kind (sun share / source share)</th><th>bake (s)</th><th>trace (s)</th><th>reference spp</th>"
            "<th>reference relMSE (estimated)</th>"
            "<th title=\"mean HDR-FLIP between the reference's two independent halves (each of half its samples)\">"
            "halves' FLIP</th><th>converged</th>"
            "<th title=\"mean relative error of SH9 irradiance against brute force on the scored pixels' normals: "
            "the least an sh frame can have on a convex Lambert object\">SH9's own error</th>"
            "<th title=\"what the sh frame gets wrong beyond SH9's own error, on 16x16-pixel blocks\">sh beyond SH9</th>"
            "</tr>\n";
    for (const CaseResult* result : sceneCases)
      html << "<tr><td class=l>" << result->environment << "</td><td>" << kindName(*result) << " ("
           << fixed(result->concentration.sunShare, 2) << " / " << fixed(result->concentration.sourceShare, 2)
           << ")</td><td>" << fixed(result->bakeSeconds, 1) << "</td><td>"
           << fixed(result->traceSeconds, 1) << "</td><td>" << result->referenceSpp << "</td><td>"
           << fixed(result->referenceRelMse, 5) << "</td><td>" << fixed(result->referenceHalvesFlip, 4)
           << "</td><td class=" << (result->referenceConverged ? "ok>yes" : "no>no")
           << "</td><td>" << fixed(100.0 * result->sh9Truncation, 1) << "%</td><td>"
           << fixed(100.0 * result->shBeyondSh9, 2) << "%</td></tr>\n";
    html << "</table>\n";
    for (const CaseResult* result : sceneCases) {
      const std::string caseName = result->scene + "-" + result->environment;
      const ModeResult* best = nullptr;
      for (const ModeResult& modeResult : result->modes)
        if (modeResult.failure.empty() && (!best || modeResult.scores.meanFlip < best->scores.meanFlip)) best = &modeResult;
      html << "<details class=case id=\"case-" << caseName << "\"><summary>" << scene << " under " << result->environment
           << " <span class=small>(" << kindName(*result) << "; reference " << result->referenceSpp << " spp"
           << (best ? "; closest mode " + best->mode + ", FLIP " + fixed(best->scores.meanFlip, 4) : std::string())
           << ")</span></summary>\n";
      for (const ModeResult& modeResult : result->modes)
        if (!modeResult.failure.empty())
          html << "<p class=no>" << modeResult.mode << ": " << escape(modeResult.failure) << "</p>\n";
      if (!result->referenceImage.empty())
        html << compareViewHtml(*result, caseName, summary.settings.width, summary.settings.height);
      html << "<div><details><summary class=small>commands</summary><pre class=small>";
      for (const std::string& command : result->commands) html << escape(command) << "\n";
      html << "</pre></details></div>\n</details>\n";
    }
  }
  html << "<p class=small>Report written in " << fixed(summary.totalSeconds, 1) << " s; " << summary.runStages
       << " stages run, " << summary.cachedStages << " taken from the cache. Thumbnails: ACES fitted tone curve, the"
          " exposure that maps the reference's median scored luminance to 0.18; heat maps: HDR-FLIP error,"
          " magma, 0 to 1.</p>\n<script>\n" << compareViewScript() << "</script>\n</body></html>\n";
  writeText(file, html.str());
}

}  // namespace iblkit
