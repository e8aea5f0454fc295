#!/usr/bin/env bash
# Installs what the build, the demo and the tests need, on a fresh Debian 12 (as root).
#   tools/setup.sh          everything: every platform's build, the tests, the release zip
#   tools/setup.sh --demo   only what the demo needs: the host's library and the engine
# Idempotent: a second run only checks. Prints the engine it will use.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
mode=all
[[ "${1:-}" == --demo ]] && mode=demo

# The engine is fetched (tools/find_godot.sh) while the packages below install: the two share nothing.
godot_log=$(mktemp)
"$repo/tools/find_godot.sh" >"$godot_log" 2>&1 &
godot_pid=$!

# Debian packages. The demo: GLM, Python for SCons, Xvfb to draw without a display (the engine brings
# its own Mesa). Everything: compilers and doctest for the core's tests, clang for the fuzzer, Mesa's
# OpenGL and Vulkan drivers, LLVM's readers and strip for the libraries, Wine and QEMU to run the core's
# tests built for Windows and for Linux arm64 (with Debian's arm64 C library), zip for the release.
debs=(libglm-dev python3 python3-venv xvfb xauth ca-certificates)
[[ $mode == all ]] && debs+=(g++ clang llvm libclang-rt-14-dev doctest-dev python3-pip libgl1-mesa-dri
  mesa-vulkan-drivers libvulkan1 wine64 qemu-user-static libc6-arm64-cross zip unzip)
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
# The demo needs SCons and Zig; the tests also gdtoolkit, numpy and Pillow.
pips=("scons>=4.5" "ziglang>=0.13")
[[ $mode == all ]] && pips+=("gdtoolkit>=4.3,<5" numpy pillow)
venv_ready() {
  [[ -x "$venv/bin/scons" ]] && "$venv/bin/python" -m ziglang version >/dev/null 2>&1 || return 1
  [[ $mode == demo ]] || { [[ -x "$venv/bin/gdlint" ]] && "$venv/bin/python" -c "import numpy, PIL" 2>/dev/null; }
}
if ! venv_ready; then
  exec 9>"$shared_dir/setup.lock"
  flock 9
  if ! venv_ready; then
    echo "setup: installing ${pips[*]} into $(readlink -f "$venv")"
    [[ -x "$venv/bin/pip" ]] || python3 -m venv "$(readlink -f "$venv")"
    "$venv/bin/pip" install -q --disable-pip-version-check "${pips[@]}"
  fi
  exec 9>&-
fi

# The engine, fetched since the start.
if ! wait "$godot_pid"; then
  cat "$godot_log" >&2; rm -f "$godot_log"; echo "setup: could not fetch the engine (above)" >&2; exit 1
fi
rm -f "$godot_log"
godot=$("$repo/tools/find_godot.sh")
echo "setup: engine $godot ($("$godot" --version | head -n 1))"
