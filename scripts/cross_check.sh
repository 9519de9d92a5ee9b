#!/usr/bin/env bash
# Cross-checks the reference path tracer against another one, Blender Cycles (Debian's blender
# 3.4), on scenes both define the same way: a sphere on a ground under real HDR maps (Lambert,
# mirror, GGX metal; a textured, a normal-mapped and a vertex-coloured glTF sphere; a 4096 x 2048 map with a
# real-sized sun; the bundled bunny). Prints, per case and region,
# the mean radiance of each tracer, their ratio and its z score, and each tracer's far ground
# against its analytic value (compare.py); docs/reference-tracer.md
# "Against another path tracer" explains the expected differences and records a run.
#
#   bash scripts/cross_check.sh [BUILD] [OUT] [SPP] [CASES]
#
# Defaults: build, out/cross-check, 512 samples per pixel (each tracer: two renders of half,
# seeds 1 and 2), every case; CASES is an extended regular expression on the case names.
#
# Not part of the tests: it installs Blender (about 110 MB of packages, as root) and takes about
# 10 minutes on 2 cores. iblkit-trace must be built (make build).
set -euo pipefail
build=${1:-build}
out=${2:-out/cross-check}
spp=${3:-512}
only=${4:-.}
here=$(cd "$(dirname "$0")/cross_check" && pwd)
trace="$build/bin/iblkit-trace"
[ -x "$trace" ] || { echo "cross_check.sh: $trace: not built (make build)" >&2; exit 1; }
if ! command -v blender >/dev/null || ! blender -b --python-expr 'import numpy' >/dev/null 2>&1; then
  [ "$(id -u)" = 0 ] || { echo "cross_check.sh: needs blender and python3-numpy (apt-get install blender python3-numpy, as root)" >&2; exit 1; }
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q blender python3-numpy >/dev/null
fi
mkdir -p "$out/inputs" "$out/scenes" "$out/renders"
out=$(cd "$out" && pwd)
run_blender() { blender -b --python-exit-code 1 --python "$@" >"$out/blender.log" 2>&1 || { tail -20 "$out/blender.log" >&2; exit 1; }; }

# Inputs: the maps without their negative texels (clean_map.py says why), two glTF spheres.
for map in venice sky studio; do
  [ -f "$out/inputs/$map.exr" ] || run_blender "$here/clean_map.py" -- "assets/hdri/$map.exr" "$out/inputs/$map.exr"
done
# And one map as its file is, negative texels included: iblkit repairs them keeping the map's
# energy, Cycles reads them as they are, so a mirror sphere (mostly direct lookups) compares the two.
[ -f "$out/inputs/sky_raw.exr" ] || cp assets/hdri/sky.exr "$out/inputs/sky_raw.exr"
# And a large map with a real-sized sun (make_sun_map.py): the sampler at 8 million texels.
[ -f "$out/inputs/sun4k.exr" ] || run_blender "$here/make_sun_map.py" -- "$out/inputs/sun4k.exr" 4096
# And the bundled bunny, whose glb is Draco-compressed (Debian's Blender has no Draco decoder):
# the same mesh as iblkit loads it, uncompressed, from a minimal bake's scene.glb.
if [ ! -f "$out/inputs/bunny.glb" ]; then
  "$build/bin/iblkit-bake" assets/models/bunny.glb --env "$out/inputs/sky.exr" -o "$out/inputs/bunny-bake" \
    --ao-rays 1 --specular-samples 1 --lut-size 8 --force >/dev/null
  cp "$out/inputs/bunny-bake/scene.glb" "$out/inputs/bunny.glb"
fi
for kind in base normal color; do
  [ -f "$out/inputs/sphere_$kind.glb" ] || run_blender "$here/make_sphere_glb.py" -- "$out/inputs/sphere_$kind.glb" "$kind"
done

# case: name, model (sphere, a glb of the inputs, or a bundled model), material JSON, map,
# environment rotation in degrees, ground height (default -1, under the unit sphere).
lambert='{"baseColor": [0.8, 0.8, 0.8], "metallic": 0, "roughness": 1, "specular": 0}'
cases=()
for map in venice sky studio; do
  cases+=("lambert_$map|sphere|$lambert|$map|0")
  cases+=("mirror_$map|sphere|{\"baseColor\": [1, 1, 1], \"metallic\": 1, \"roughness\": 0}|$map|0")
  cases+=("ggx0.3_$map|sphere|{\"baseColor\": [1, 1, 1], \"metallic\": 1, \"roughness\": 0.3}|$map|0")
  cases+=("ggx0.7_$map|sphere|{\"baseColor\": [1, 1, 1], \"metallic\": 1, \"roughness\": 0.7}|$map|0")
done
cases+=("lambert_sun4k|sphere|$lambert|sun4k|0")
cases+=("ggx0.3_sun4k|sphere|{\"baseColor\": [1, 1, 1], \"metallic\": 1, \"roughness\": 0.3}|sun4k|0")
cases+=("mirror_sky_rotated60|sphere|{\"baseColor\": [1, 1, 1], \"metallic\": 1, \"roughness\": 0}|sky|60")
cases+=("mirror_sky_raw|sphere|{\"baseColor\": [1, 1, 1], \"metallic\": 1, \"roughness\": 0}|sky_raw|0")
cases+=("texture_venice|sphere_base.glb|{\"metallic\": 0, \"roughness\": 1, \"specular\": 0}|venice|0")
cases+=("bunny_lambert_sky|bunny.glb|$lambert|sky|0|-0.891")
cases+=("normalmap_venice|sphere_normal.glb|{\"metallic\": 0, \"roughness\": 1, \"specular\": 0}|venice|0")
cases+=("vertexcolor_venice|sphere_color.glb|{\"metallic\": 0, \"roughness\": 1, \"specular\": 0}|venice|0")

results="$out/results.jsonl"
: >"$results"
half=$((spp / 2))
for entry in "${cases[@]}"; do
  IFS='|' read -r name model material map rotation ground <<<"$entry"
  [[ $name =~ $only ]] || continue
  if [ "$model" = sphere ]; then model_json="{\"shape\": \"sphere\", \"material\": $material}"
  else model_json="{\"file\": \"../inputs/$model\", \"material\": $material}"; fi
  scene="$out/scenes/$name.json"
  cat >"$scene" <<JSON
{ "models": [ $model_json ],
  "ground": {"enabled": true, "height": ${ground:--1}, "size": 20, "material": $lambert},
  "environment": {"file": "../inputs/$map.exr", "rotation": $rotation, "intensity": 1},
  "camera": {"position": [0.5, 1.2, 4.5], "target": [0, -0.3, 0], "yfov": 45},
  "width": 240, "height": 135 }
JSON
  r="$out/renders/$name"
  extra=()
  for seed in 1 2; do
    layers=()  # the regions' layers and the normal, from the first render only
    [ "$seed" = 1 ] && layers=(--mask "${r}_mask.exr" --depth "${r}_depth.exr" --normal "${r}_iblkit_normal.exr")
    "$trace" "$scene" --spp "$half" --seed "$seed" --max-depth 64 --texture-footprint 0 -o "${r}_iblkit_$seed.exr" \
      "${layers[@]}" >/dev/null
    run_blender "$here/cycles_scene.py" -- "$scene" "${r}_cycles_$seed.exr" "$half" "$seed"
  done
  if [[ $name == normalmap* ]]; then
    run_blender "$here/cycles_scene.py" -- "$scene" "${r}_cycles_normal.exr" 16 1 normal
    extra=("${r}_iblkit_normal.exr" "${r}_cycles_normal.exr")
  fi
  blender -b --python-exit-code 1 --python "$here/compare.py" -- "$name" "${r}_iblkit_1.exr" "${r}_iblkit_2.exr" "${r}_cycles_1.exr" \
    "${r}_cycles_2.exr" "${r}_mask.exr" "${r}_depth.exr" "$out/inputs/$map.exr" "${extra[@]}" 2>/dev/null |
    sed -n 's/^CROSS_CHECK //p' | tee -a "$results"
done

# The table: Cycles / iblkit per region (z in brackets).
python3 - "$results" <<'PY' | tee "$out/summary.md"
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
regions = ["objects", "ground", "sky", "objects, normals within 1 degree"]
print("| case | " + " | ".join(regions) + " | far ground / analytic: iblkit, Cycles |")
print("| --- |" + " --- |" * (len(regions) + 1))
for row in rows:
    cells = ["%.4f (z %.1f)" % (row[r]["ratio"], row[r]["z"]) if r in row else "" for r in regions]
    far = row.get("far ground / analytic")
    cells.append("%.4f, %.4f" % (far["iblkit"], far["cycles"]) if far else "")
    print("| %s | %s |" % (row["case"], " | ".join(cells)))
PY

# What the definitions alone predict for the cases where Cycles 3.4 differs (expected_differences.py).
run_blender "$here/expected_differences.py" -- assets/hdri/sky.exr
grep '^expected:' "$out/blender.log" | tee -a "$out/summary.md"
