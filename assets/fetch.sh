#!/usr/bin/env bash
# Fetches the CC0 assets of @pmndrs/assets (18 HDR environment maps as 512x256 OpenEXR, the
# Draco-compressed bunny and suzi meshes) with `npm pack`, decodes the base64 data: URIs inside
# its .js modules into assets/hdri and assets/models, and verifies them against manifest.sha256.
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

mkdir -p "$here/hdri" "$here/models"
while read -r _ path; do
  name=$(basename "$path")
  case "$path" in
    hdri/*) decode "$work/package/hdri/$name.js" "$here/$path" ;;
    models/*) decode "$work/package/models/$name.js" "$here/$path" ;;
  esac
done <"$manifest"

if ! (cd "$here" && sha256sum --quiet -c "$manifest"); then
  echo "assets: checksum mismatch against $manifest (the package changed or the download is corrupt)" >&2
  exit 1
fi
echo "assets: $(wc -l <"$manifest") files decoded and verified in $here"
