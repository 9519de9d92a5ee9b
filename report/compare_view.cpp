#include "report/compare_view.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "core/tone_curve_constants.h"
#include "report/html_text.h"

namespace iblkit {

namespace {

std::string attribute(const std::string& text) { return escapeHtml(text); }
std::string fixed(double value, int digits) { return fixedText(value, digits); }

constexpr const char* kScript = R"JS(
"use strict";
// The tone curve of core/tone_curve.cpp: display = sRGB_OETF(min(aces(x 2^stops), 1)), rounded to 8 bits.
function acesFitted(x) {
  if (!(x > 0)) return 0;
  if (x === Infinity) return 1;
  return Math.min((x * (ACES.a * x + ACES.b)) / (x * (ACES.c * x + ACES.d) + ACES.e), 1);
}
function srgbEncode(v) {
  const x = v > 0 ? Math.min(v, 1) : 0;
  return x <= SRGB.limit ? SRGB.slope * x : SRGB.scale * Math.pow(x, 1 / SRGB.gamma) - SRGB.offset;
}
function quantize(v) { return Math.round(Math.min(Math.max(v, 0), 1) * 255); }

// The cases' linear images (images/CASE-linear.js calls iblkitCaseImages), decoded on demand.
const caseData = {}, caseLoads = {}, decoded = {};
window.iblkitCaseImages = function (name, data) {
  caseData[name] = data;
  if (caseLoads[name] && caseLoads[name].resolve) caseLoads[name].resolve(data);
};
function loadCase(name, script) {
  if (caseData[name]) return Promise.resolve(caseData[name]);
  if (!caseLoads[name]) {
    const load = {};
    load.promise = new Promise((resolve, reject) => {
      load.resolve = resolve;
      const element = document.createElement("script");
      element.src = script;
      element.onerror = () => reject(new Error("cannot load " + script));
      document.head.appendChild(element);
    });
    caseLoads[name] = load;
  }
  return caseLoads[name].promise;
}
async function linearImage(name, script, key) {
  const id = name + "/" + key;
  if (!decoded[id]) decoded[id] = (async () => {
    const data = await loadCase(name, script);
    if (!(key in data.images)) throw new Error(name + ": no linear image " + key);
    const text = atob(data.images[key]);
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
    const rgbe = new Uint8Array(await new Response(stream).arrayBuffer());
    const count = data.width * data.height;
    if (rgbe.length !== 4 * count) throw new Error(name + "/" + key + ": " + rgbe.length + " bytes, not " + 4 * count);
    const linear = new Float32Array(3 * count);
    for (let i = 0; i < count; ++i) {
      const e = rgbe[4 * i + 3];
      if (e === 0) continue;
      const f = Math.pow(2, e - 136);
      for (let c = 0; c < 3; ++c) linear[3 * i + c] = (rgbe[4 * i + c] + 0.5) * f;
    }
    return {width: data.width, height: data.height, linear};
  })();
  return decoded[id];
}
function toneMapInto(canvas, image, stops) {
  canvas.width = image.width;
  canvas.height = image.height;
  const context = canvas.getContext("2d");
  const pixels = context.createImageData(image.width, image.height);
  const scale = Math.pow(2, stops), d = pixels.data, linear = image.linear;
  for (let i = 0; i < image.width * image.height; ++i) {
    for (let c = 0; c < 3; ++c) d[4 * i + c] = quantize(srgbEncode(acesFitted(linear[3 * i + c] * scale)));
    d[4 * i + 3] = 255;
  }
  context.putImageData(pixels, 0, 0);
}

let activeViewer = null;
const viewers = [];
class Viewer {
  constructor(element) {
    this.element = element;
    this.name = element.dataset.case;
    this.script = element.dataset.linear;
    this.exposure = parseFloat(element.dataset.exposure);
    this.width = parseInt(element.dataset.width);
    this.items = Array.from(element.querySelectorAll(".items button"));
    this.image = element.querySelector("img.large");
    this.canvas = element.querySelector("canvas.large");
    this.caption = element.querySelector(".caption");
    this.exposureInput = element.querySelector("input.exposure");
    this.exposureText = element.querySelector("output.exposure");
    this.zoomInput = element.querySelector("select.zoom");
    this.index = 0;
    this.stops = 0;
    this.token = 0;
    this.items.forEach((button, i) => {
      button.addEventListener("click", () => { this.select(i); activeViewer = this; });
      button.addEventListener("mouseenter", () => this.show(i));
      button.addEventListener("mouseleave", () => this.show(this.index));
    });
    this.exposureInput.addEventListener("input", () => this.setStops(parseFloat(this.exposureInput.value)));
    this.zoomInput.addEventListener("change", () => this.applyZoom());
    element.addEventListener("mouseenter", () => { activeViewer = this; });
    element.addEventListener("focusin", () => { activeViewer = this; });
    this.applyZoom();
    this.show(0);
  }
  select(i) {
    const n = this.items.length;
    this.index = ((i % n) + n) % n;
    this.show(this.index);
  }
  // The item of mode number k (0: the reference), and the heat map of the shown mode or back.
  selectMode(k) {
    const modes = this.items.filter((button) => !button.dataset.heat);
    if (k < modes.length) this.select(this.items.indexOf(modes[k]));
  }
  toggleHeat() {
    const shown = this.items[this.index], key = shown.dataset.key;
    const target = this.items.find((button) => button.dataset.key === key && button.dataset.heat !== shown.dataset.heat);
    if (target) this.select(this.items.indexOf(target));
  }
  setStops(stops) {
    this.stops = Math.max(-8, Math.min(8, stops));
    this.exposureInput.value = this.stops;
    this.exposureText.value = (this.stops >= 0 ? "+" : "") + this.stops.toFixed(2);
    this.show(this.index);
  }
  applyZoom() {
    const width = this.width * parseFloat(this.zoomInput.value) + "px";
    this.image.style.width = width;
    this.canvas.style.width = width;
  }
  zoomBy(step) {
    const options = Array.from(this.zoomInput.options);
    const next = Math.max(0, Math.min(options.length - 1, this.zoomInput.selectedIndex + step));
    this.zoomInput.selectedIndex = next;
    this.applyZoom();
  }
  show(i) {
    const button = this.items[i];
    this.items.forEach((other, j) => other.classList.toggle("on", j === this.index));
    this.items.forEach((other, j) => other.classList.toggle("shown", j === i));
    this.element.dataset.shown = button.dataset.src;
    this.image.setAttribute("src", button.dataset.src);
    this.caption.textContent = button.dataset.label + (button.dataset.heat ? "" : ", exposure " +
        (this.stops >= 0 ? "+" : "") + this.stops.toFixed(2) + " stops from the case's");
    const token = ++this.token;
    if (button.dataset.heat || this.stops === 0) {
      this.image.hidden = false;
      this.canvas.hidden = true;
      this.element.dataset.drawn = "png";
      return;
    }
    linearImage(this.name, this.script, button.dataset.key).then((image) => {
      if (token !== this.token) return;
      toneMapInto(this.canvas, image, this.exposure + this.stops);
      this.image.hidden = true;
      this.canvas.hidden = false;
      this.element.dataset.drawn = "canvas";
    }).catch((error) => {
      this.caption.textContent = "exposure control unavailable: " + error.message;
      console.warn(error.message);
    });
  }
}
function currentViewer() {
  const open = (viewer) => viewer && viewer.element.closest("details") && viewer.element.closest("details").open;
  if (open(activeViewer)) return activeViewer;
  return viewers.find(open) || null;
}
document.addEventListener("keydown", (event) => {
  if (event.ctrlKey || event.metaKey || event.altKey) return;
  const tag = event.target && event.target.tagName;
  if (tag === "INPUT" || tag === "SELECT" || tag === "TEXTAREA") return;
  const viewer = currentViewer();
  if (!viewer) return;
  const key = event.key;
  if (key === "ArrowRight" || key === "n") viewer.select(viewer.index + 1);
  else if (key === "ArrowLeft" || key === "p") viewer.select(viewer.index - 1);
  else if (key >= "1" && key <= "9") viewer.selectMode(parseInt(key) - 1);
  else if (key === "h") viewer.toggleHeat();
  else if (key === "+" || key === "=") viewer.zoomBy(1);
  else if (key === "-") viewer.zoomBy(-1);
  else if (key === "]") viewer.setStops(viewer.stops + 0.5);
  else if (key === "[") viewer.setStops(viewer.stops - 0.5);
  else if (key === "0") viewer.setStops(0);
  else return;
  event.preventDefault();
});
document.querySelectorAll(".viewer").forEach((element) => viewers.push(new Viewer(element)));
// For tests: the page's own tone mapping of a case's linear image, as a PNG data URL.
window.iblkitToneMapped = async function (name, script, key, stops) {
  const canvas = document.createElement("canvas");
  toneMapInto(canvas, await linearImage(name, script, key), stops);
  return canvas.toDataURL("image/png");
};
)JS";

}  // namespace

std::string compareViewStyle() {
  return ".viewer{margin:.5em 0;outline:none}.viewer .bar{font-size:12px;margin:4px 0}"
         ".viewer .items button{font-size:12px;margin:1px;padding:2px 6px;border:1px solid #bbb;background:#f8f8f8;"
         "cursor:pointer}.viewer .items button.heat{color:#730}.viewer .items button.on{background:#246;color:#fff}"
         ".viewer .items button.shown{border-color:#c30}.viewer .stage{overflow:auto;max-width:100%;max-height:85vh;"
         "border:1px solid #ccc;background:#111;width:fit-content}.viewer .stage img,.viewer .stage canvas{display:block;"
         "image-rendering:pixelated}.viewer .caption{font-size:12px;color:#333;margin:3px 0}"
         ".keys{font-size:12px;color:#555}";
}

std::string compareViewScript() {
  // The shortest text that reads back as the same double (std::to_chars), so JavaScript's numbers are core's.
  const auto exact = [](double value) {
    char buffer[64];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof(buffer), value).ptr);
  };
  const AcesFitCoefficients& k = kAcesFitted;
  return "const ACES = {a: " + exact(k.a) + ", b: " + exact(k.b) + ", c: " + exact(k.c) + ", d: " + exact(k.d) +
         ", e: " + exact(k.e) + "};\nconst SRGB = {limit: " + exact(kSrgbLinearLimit) + ", slope: " +
         exact(kSrgbSlope) + ", scale: " + exact(kSrgbScale) + ", offset: " + exact(kSrgbOffset) +
         ", gamma: " + exact(kSrgbGamma) + "};\n" + kScript;
}

std::string compareViewHtml(const CaseResult& result, const std::string& caseName, int width, int height) {
  std::ostringstream html;
  const int zoom = std::clamp(960 / std::max(width, 1), 1, 4);
  html << "<div class=viewer tabindex=0 data-case=\"" << attribute(caseName) << "\" data-linear=\""
       << attribute(result.linearImages) << "\" data-exposure=\"" << result.exposure << "\" data-width=\"" << width
       << "\">\n<div class=bar><span class=items>";
  int number = 1;
  const auto button = [&](const std::string& key, const std::string& src, const std::string& label, bool heat,
                          const std::string& text) {
    html << "<button type=button data-key=\"" << attribute(key) << "\" data-src=\"" << attribute(src)
         << "\" data-label=\"" << attribute(label) << "\"" << (heat ? " data-heat=1 class=heat" : "") << ">"
         << text << "</button>";
  };
  button("reference", result.referenceImage, "reference, " + std::to_string(result.referenceSpp) + " spp", false,
         std::to_string(number++) + " reference");
  for (const ModeResult& mode : result.modes) {
    if (!mode.failure.empty()) continue;
    const std::string flip = "FLIP " + fixed(mode.scores.meanFlip, 4);
    button(mode.mode, mode.image, mode.mode + ": " + flip, false,
           (number <= 9 ? std::to_string(number) + " " : std::string()) + mode.mode);
    ++number;
    button(mode.mode, mode.heatMap, mode.mode + ": FLIP heat map (magma, 0 to 1), mean " + flip, true, "heat");
  }
  html << "</span><br>exposure <input class=exposure type=range min=-8 max=8 step=0.25 value=0>"
       << "<output class=exposure>+0.00</output> stops &nbsp; zoom <select class=zoom>";
  for (const int option : {1, 2, 3, 4, 6, 8})
    html << "<option value=" << option << (option == zoom ? " selected" : "") << ">" << option << "x</option>";
  html << "</select> <span class=keys>keys: &larr; &rarr; or n p flip, 1-9 reference and modes, h heat map, "
          "+ - zoom, [ ] exposure, 0 the case's exposure</span></div>\n"
       << "<div class=stage><img class=large alt=\"\" width=" << width << " height=" << height << " src=\""
       << attribute(result.referenceImage) << "\"><canvas class=large hidden></canvas></div>\n"
       << "<div class=caption></div>\n</div>\n";
  return html.str();
}

}  // namespace iblkit
