#!/usr/bin/env bash
# Installs everything the build, the demo and the tests need, on a fresh Debian 12 (as root).
# Idempotent: a second run only checks. Prints the engine it will use.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

# Debian packages: compilers, GLM, doctest, clang for the fuzzer, Xvfb + Mesa for rendering.
debs=(g++ clang libclang-rt-14-dev libglm-dev doctest-dev python3 python3-venv python3-pip
  xvfb xauth libgl1-mesa-dri mesa-vulkan-drivers libvulkan1 ca-certificates)
missing=()
for p in "${debs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [[ $(id -u) -eq 0 ]] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Python tools (SCons, gdtoolkit) in a private virtual environment.
venv="$repo/.cache/venv"
if [[ ! -x "$venv/bin/scons" || ! -x "$venv/bin/gdlint" ]]; then
  echo "setup: creating $venv with scons and gdtoolkit"
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check "scons>=4.5" "gdtoolkit>=4.3,<5"
fi

# The engine.
godot=$("$repo/tools/find_godot.sh")
echo "setup: engine $godot ($("$godot" --version | head -n 1))"
