#!/usr/bin/env bash
# Fetches the CC0 assets of @pmndrs/assets (18 HDR environment maps as 512x256 OpenEXR, the
# Draco-compressed bunny and suzi meshes, the textured pmndrs.glb, 29 tileable normal maps and 4
# textures as WebP) with `npm pack`, decodes the base64 data: URIs inside its .js modules into
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
if ! (cd "$work" && npm pack --silent "$package" >npm.log 2>&1); then
  echo "assets: could not download $package with npm pack (offline, or the registry is unreachable):" >&2
  tail -n 3 "$work/npm.log" >&2
  exit 1
fi
tar -xzf "$work"/pmndrs-assets-*.tgz -C "$work"

# Each module reads: export default 'data:<mime>;base64,<payload>'
decode() {
  local src=$1 dst=$2
  sed -E -e "s/^[^,]*base64,//" -e "s/['\"];?[[:space:]]*$//" "$src" | tr -d '\n' | base64 -d >"$dst.tmp"
  mv "$dst.tmp" "$dst"
}

mkdir -p "$here/hdri" "$here/models" "$here/normals" "$here/textures"
while read -r _ path; do
  case "$path" in
    hdri/* | models/* | normals/* | textures/*) decode "$work/package/$path.js" "$here/$path" ;;
    *) echo "assets: $manifest: unexpected path $path" >&2; exit 1 ;;
  esac
done <"$manifest"

if ! (cd "$here" && sha256sum --quiet -c "$manifest"); then
  echo "assets: checksum mismatch against $manifest (the package changed or the download is corrupt)" >&2
  exit 1
fi
echo "assets: $(wc -l <"$manifest") files decoded and verified in $here"
