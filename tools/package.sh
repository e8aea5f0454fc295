#!/usr/bin/env bash
# Makes the release zip: build/dist/sunflower_field-<version>.zip holding addons/sunflower_field/
# with every library built (tools/build.sh --all first), the LICENSE and the addon's README.
# Unzip it into a Godot project's folder and enable the plugin.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
version=$(sed -n 's/^version="\(.*\)"/\1/p' "$repo/addons/sunflower_field/plugin.cfg")
dist="$repo/build/dist"
zip="$dist/sunflower_field-$version.zip"
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/addons" "$dist"
cp -rL "$repo/addons/sunflower_field" "$stage/addons/"
# Build by-products that no project needs: import libraries, debug databases.
rm -f "$stage"/addons/sunflower_field/bin/*.{lib,pdb}
count=$(ls "$stage"/addons/sunflower_field/bin/ | wc -l)
((count > 0)) || { echo "package: no libraries in addons/sunflower_field/bin; run tools/build.sh --all" >&2; exit 1; }
rm -f "$zip"
(cd "$stage" && zip -qr -X "$zip" addons)
echo "package: $zip ($count libraries, $(du -h "$zip" | cut -f1))"
