#!/usr/bin/env bash
# The demo: iblkit's main job on the bundled assets and scenes.
#  1. Reads and checks every environment map, model and scene (iblkit-info), with tone-mapped
#     previews of the maps: out/demo/inputs.html and inputs.json.
#  2. iblkit-report: bakes every bundled scene under six maps, renders every engine mode headless,
#     path-traces the references and scores each mode: out/demo/report.html and report.json
#     (docs/report.md). Stages are cached in out/demo/cache, so a re-run is fast.
set -euo pipefail
build=${1:-build}
bin="$build/bin"
out=${IBLKIT_DEMO_OUT:-out/demo}  # tests run it into a scratch folder
mkdir -p "$out/maps"
warnings="$out/warnings.log"
: >"$warnings"

# One number out of iblkit-info's one-line JSON.
field() { sed -E "s/.*\"$2\":([^,}]*).*/\1/" <<<"$1"; }

json="$out/inputs.json.tmp"
echo '{"assets": [' >"$json"
first=1
rows=""
for map in assets/hdri/*.exr; do
  name=$(basename "$map" .exr)
  line=$("$bin/iblkit-info" --json --png "$out/maps/$name.png" "$map" 2>>"$warnings")
  [ $first -eq 1 ] || echo ',' >>"$json"
  first=0
  printf '%s' "$line" >>"$json"
  caption=$(printf 'max luminance %.4g, mean %.4g' "$(field "$line" maxLuminance)" "$(field "$line" meanLuminance)")
  rows+="<figure><img src=\"maps/$name.png\" width=\"256\" height=\"128\"><figcaption><b>$name</b><br>$caption</figcaption></figure>"$'\n'
done
scene_rows=""
for scene in assets/models/*.glb assets/scenes/*.json; do
  line=$("$bin/iblkit-info" --json "$scene" 2>>"$warnings")
  echo ',' >>"$json"
  printf '%s' "$line" >>"$json"
  scene_rows+="<tr><td>$(basename "$scene")</td><td>$(field "$line" meshes)</td><td>$(field "$line" vertices)</td><td>$(field "$line" triangles)</td><td>$(field "$line" camera)</td><td>$(field "$line" environment)</td></tr>"$'\n'
done

echo ']}' >>"$json"
mv "$json" "$out/inputs.json"

cat >"$out/inputs.html.tmp" <<HTML
<!doctype html>
<html><head><meta charset="utf-8"><title>iblkit demo: inputs</title>
<style>body{font-family:sans-serif;margin:2em;max-width:1200px}figure{display:inline-block;margin:.5em;vertical-align:top;width:256px}
figcaption{font-size:12px}code{font-size:11px}table{border-collapse:collapse}td{border:1px solid #ccc;padding:4px}</style></head>
<body><h1>iblkit demo: the inputs</h1>
<p>Every bundled environment map, model and scene, read and checked by the core library
(<a href="report.html">the report</a> scores the real-time modes against the path tracer on them).
Previews use the shared tone curve (ACES fitted, sRGB) at exposure 0.</p>
<h2>Environment maps</h2>
$rows
<h2>Models and scenes</h2>
<table><tr><th>file</th><th>meshes</th><th>vertices</th><th>triangles</th><th>camera</th><th>environment</th></tr>
$scene_rows</table>
<h2>Repairs</h2>
<pre>$(cat "$warnings")</pre>
</body></html>
HTML
mv "$out/inputs.html.tmp" "$out/inputs.html"
echo "demo: wrote $out/inputs.html ($(wc -l <"$warnings") loader warnings in $warnings)"

# --force: the folder already holds this script's own inputs.html and maps/, which the report keeps.
# The references are traced to the report's own bound (estimated relMSE <= 1e-3, docs/report.md):
# since the environment samples follow the bilinear radiance and the vertex's normal the 36 cases
# fit in the demo's 15 minutes (docs/report.md, "The absolute bound's cost"). IBLKIT_REPORT_OPTIONS
# adds options (e.g. "--max-reference-relmse 1" for the looser rule of before).
report_options=${IBLKIT_REPORT_OPTIONS-}
"$bin/iblkit-report" -o "$out" --force $report_options
