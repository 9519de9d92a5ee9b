#!/usr/bin/env bash
# The demo: runs every stage of the pipeline that exists on the bundled assets and scenes and
# writes out/demo/report.html (static, no server needed) and out/demo/report.json.
# Stages so far: read and check every environment map, model and scene (iblkit-info), with
# tone-mapped previews of the maps; bake every bundled scene (iblkit-bake) and path-trace its
# reference image (iblkit-trace). Scoring of the real-time engine against it comes with the engine.
set -euo pipefail
build=${1:-build}
bin="$build/bin"
out=out/demo
mkdir -p "$out/maps"
warnings="$out/warnings.log"
: >"$warnings"

# One number out of iblkit-info's one-line JSON.
field() { sed -E "s/.*\"$2\":([^,}]*).*/\1/" <<<"$1"; }

json="$out/report.json.tmp"
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

# Bake and reference render of each bundled scene.
mkdir -p "$out/bake" "$out/trace"
render_rows=""
for scene in assets/scenes/*.json; do
  name=$(basename "$scene" .json)
  bake_log=$("$bin/iblkit-bake" "$scene" -o "$out/bake/$name" 2>>"$warnings")
  trace_log=$("$bin/iblkit-trace" "$scene" -o "$out/trace/$name.exr" --png "$out/trace/$name.png" \
    --exposure -1 --spp "${IBLKIT_DEMO_SPP:-32}" --width 480 --height 270 2>>"$warnings")
  echo ',' >>"$json"
  printf '{"scene": "%s", "bake": %s, "trace": "%s"}' "$scene" "$(cat "$out/bake/$name/bake.json")" "$trace_log" >>"$json"
  render_rows+="<figure style=\"width:480px\"><img src=\"trace/$name.png\" width=\"480\" height=\"270\"><figcaption><b>$name</b>: path traced, $trace_log<br>bake: $bake_log</figcaption></figure>"$'\n'
done
echo ']}' >>"$json"
mv "$json" "$out/report.json"

cat >"$out/report.html.tmp" <<HTML
<!doctype html>
<html><head><meta charset="utf-8"><title>iblkit demo</title>
<style>body{font-family:sans-serif;margin:2em;max-width:1200px}figure{display:inline-block;margin:.5em;vertical-align:top;width:256px}
figcaption{font-size:12px}code{font-size:11px}table{border-collapse:collapse}td{border:1px solid #ccc;padding:4px}</style></head>
<body><h1>iblkit demo</h1>
<p>Stages that exist so far: every bundled environment map, model and scene is read and checked by the
core library. Previews use the shared tone curve (ACES fitted, sRGB): maps at exposure 0, renders at -1.
Scoring of the real-time approximations against the path tracer will appear here.</p>
<h2>Reference renders (iblkit-trace, path integrator) and bakes (iblkit-bake)</h2>
$render_rows
<h2>Environment maps</h2>
$rows
<h2>Models and scenes</h2>
<table><tr><th>file</th><th>meshes</th><th>vertices</th><th>triangles</th><th>camera</th><th>environment</th></tr>
$scene_rows</table>
<h2>Repairs</h2>
<pre>$(cat "$warnings")</pre>
</body></html>
HTML
mv "$out/report.html.tmp" "$out/report.html"
echo "demo: wrote $out/report.html and $out/report.json ($(wc -l <"$warnings") loader warnings in $warnings)"
