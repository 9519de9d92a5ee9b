#!/usr/bin/env bash
# Fetches the CC0 assets of @pmndrs/assets (18 HDR environment maps as 512x256 OpenEXR, the
# Draco-compressed bunny and suzi meshes, the textured pmndrs.glb, 29 tileable normal maps and 4
# textures as WebP; and pmndrs.glb's embedded AO atlas as a JPEG of its own) with `npm pack`, decodes the base64 data: URIs inside its .js modules into
# assets/hdri, assets/models, assets/normals and assets/textures, and verifies them against
# manifest.sha256. One download of the package (about 8 MB) holds them all.
# Quick when the files are already there and verified.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
package="@pmndrs/assets@1.7.0"
manifest="$here/manifest.sha256"

if (cd "$here" && sha256sum --quiet -c "$manifest" >/dev/null 2>&1); then
  echo "assets: all $(wc -l <"$manifest") files present and verified"
  exit 0
fi

command -v npm >/dev/null 2>&1 || { echo "assets: npm not found; run scripts/setup.sh first" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "assets: fetching $package from the npm registry"
# Three tries, 5 s apart: a registry connection that drops once does not fail a CI run.
for try in 1 2 3; do
  if (cd "$work" && npm pack --silent "$package" >npm.log 2>&1); then break; fi
  if [ "$try" = 3 ]; then
    echo "assets: 'npm pack $package' failed 3 times (offline, or the registry is unreachable):" >&2
    tail -n 3 "$work/npm.log" >&2
    exit 1
  fi
  echo "assets: 'npm pack $package' failed (try $try of 3), retrying in 5 s" >&2
  sleep 5
done
tar -xzf "$work"/pmndrs-assets-*.tgz -C "$work"

# Each module reads: export default 'data:<mime>;base64,<payload>'
decode() {
  local src=$1 dst=$2
  sed -E -e "s/^[^,]*base64,//" -e "s/['\"];?[[:space:]]*$//" "$src" | tr -d '\n' | base64 -d >"$dst.tmp"
  mv "$dst.tmp" "$dst"
}

# textures/pmndrs_ao.jpg: the JPEG pmndrs.glb embeds (its image "ao", buffer view 0: a baked
# ambient-occlusion atlas the asset uses as its baseColorTexture), as a file of its own, so that a
# scene file can assign it as the model's glTF occlusionTexture (assets/scenes/tiles.json). Read
# from the GLB container (glTF 2.0 section 4.4): the JSON chunk's length at byte 12, the JSON from
# byte 20, the BIN chunk's data 8 bytes after it; the view's offset and length from the JSON.
extract_view0() {
  local glb=$1 dst=$2 json_length view offset length
  json_length=$(od -An -t u4 -j 12 -N 4 "$glb" | tr -d ' ')
  view=$(dd if="$glb" bs=1 skip=20 count="$json_length" 2>/dev/null | grep -o '"bufferViews":\[{[^}]*}')
  offset=$(sed -E 's/.*"byteOffset":([0-9]+).*/\1/' <<<"$view")
  length=$(sed -E 's/.*"byteLength":([0-9]+).*/\1/' <<<"$view")
  # One dd, not tail | head: under pipefail, head's early exit kills tail with SIGPIPE (status
  # 141), a race that failed a CI run.
  dd if="$glb" of="$dst.tmp" iflag=skip_bytes,count_bytes skip=$((20 + json_length + 8 + offset)) \
    count="$length" status=none
  mv "$dst.tmp" "$dst"
}

mkdir -p "$here/hdri" "$here/models" "$here/normals" "$here/textures"
# The manifest is sorted by path, so models/pmndrs.glb is decoded before textures/pmndrs_ao.jpg.
while read -r _ path; do
  case "$path" in
    textures/pmndrs_ao.jpg) extract_view0 "$here/models/pmndrs.glb" "$here/$path" ;;
    hdri/* | models/* | normals/* | textures/*) decode "$work/package/$path.js" "$here/$path" ;;
    *) echo "assets: $manifest: unexpected path $path" >&2; exit 1 ;;
  esac
done <"$manifest"

if ! (cd "$here" && sha256sum --quiet -c "$manifest"); then
  echo "assets: checksum mismatch against $manifest (the package changed or the download is corrupt)" >&2
  exit 1
fi
echo "assets: $(wc -l <"$manifest") files decoded and verified in $here"
