#!/usr/bin/env bash
# Installs everything the build, the demo and the tests need, on a fresh Debian 12 (as root).
# Idempotent: a second run only checks. Prints the engine it will use.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

# Debian packages: compilers, GLM, doctest, clang for the fuzzer, Xvfb + Mesa for rendering.
# LLVM's readers check the built libraries; Wine and QEMU run the core's tests built for Windows
# and for Linux arm64 (with Debian's arm64 C library); zip packs the release.
debs=(g++ clang llvm libclang-rt-14-dev libglm-dev doctest-dev python3 python3-venv python3-pip
  xvfb xauth libgl1-mesa-dri mesa-vulkan-drivers libvulkan1 ca-certificates wine64 qemu-user-static
  libc6-arm64-cross zip unzip)
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

# Python tools in a virtual environment: SCons, gdtoolkit, Zig's C/C++ compiler (which
# cross-compiles the libraries for every desktop platform), numpy and Pillow (picture measurements).
# It lives outside the clone ($SUNFLOWER_FIELD_CACHE, default ~/.cache/sunflower_field) and
# .cache/venv links to it: Zig builds its C and C++ libraries once per target (1.5–2 min each here)
# into its cache, which only a Zig at the same place finds again, so every clone on this machine
# shares one (without a writable home: the clone's own .cache). Clones setting up at once take turns.
venv="$repo/.cache/venv"
home_cache=${XDG_CACHE_HOME:-${HOME:+$HOME/.cache}}
shared_dir=${SUNFLOWER_FIELD_CACHE:-${home_cache:+$home_cache/sunflower_field}}
mkdir -p "$repo/.cache"
if [[ -z "$shared_dir" ]] || ! mkdir -p "$shared_dir" 2>/dev/null; then
  shared_dir=$repo/.cache/shared
  mkdir -p "$shared_dir"
fi
if [[ ! -e "$venv" && ! -L "$venv" ]]; then
  ln -s "$shared_dir/venv" "$venv"
fi
venv_ready() {
  [[ -x "$venv/bin/scons" && -x "$venv/bin/gdlint" ]] && "$venv/bin/python" -m ziglang version >/dev/null 2>&1 &&
    "$venv/bin/python" -c "import numpy, PIL" 2>/dev/null
}
if ! venv_ready; then
  exec 9>"$shared_dir/setup.lock"
  flock 9
  if ! venv_ready; then
    echo "setup: creating $(readlink -f "$venv") with scons, gdtoolkit, ziglang, numpy and pillow"
    python3 -m venv "$(readlink -f "$venv")"
    "$venv/bin/pip" install -q --disable-pip-version-check "scons>=4.5" "gdtoolkit>=4.3,<5" "ziglang>=0.13" numpy pillow
  fi
  exec 9>&-
fi

# The engine.
godot=$("$repo/tools/find_godot.sh")
echo "setup: engine $godot ($("$godot" --version | head -n 1))"
