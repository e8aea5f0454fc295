#!/usr/bin/env bash
# Builds everything: the extension (debug + release) into the addon, the core unit tests, and the
# imported caches of the demo and test projects. Without arguments: the libraries for this machine
# (Linux x86_64). --all: the libraries for Linux, Windows and macOS on x86_64 and arm64, and the core's
# tests for Windows x86_64 and Linux arm64. Other arguments go to scons.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/setup.sh"
godot=$("$repo/tools/find_godot.sh")
cd "$repo"
args=()
for arg in "$@"; do
  if [[ "$arg" == --all ]]; then
    args+=(platform=all arch=all cross_tests=windows.x86_64,linux.arm64)
  else
    args+=("$arg")
  fi
done
"$repo/.cache/venv/bin/scons" -Q -j"$(nproc)" godot="$godot" "${args[@]}"
"$repo/tools/import_project.sh" "$repo/tests/godot"
"$repo/tools/import_project.sh" "$repo/demo_project"
