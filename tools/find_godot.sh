#!/usr/bin/env bash
# Prints the command that starts a Godot >= 4.5 engine, fetching one if needed.
#
# Order: $GODOT, a `godot` on PATH that is new enough, the engine unpacked earlier
# into .cache/godot/, else Debian unstable's `godot` package unpacked there through a
# private apt configuration (the system's apt sources are never touched).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
cache="$repo/.cache/godot"
wrapper="$cache/godot"
# Bump when the unpacked set changes, so older caches are refreshed.
marker="$cache/.complete-2"

version_ok() { # $1 = command; true when it reports 4.5 or newer
  local v
  v=$("$1" --version 2>/dev/null | head -n 1) || return 1
  [[ "$v" =~ ^([0-9]+)\.([0-9]+) ]] || return 1
  local major=${BASH_REMATCH[1]} minor=${BASH_REMATCH[2]}
  ((major > 4 || (major == 4 && minor >= 5)))
}

if [[ -n "${GODOT:-}" ]]; then
  version_ok "$GODOT" || { echo "find_godot: \$GODOT=$GODOT is not a Godot >= 4.5" >&2; exit 1; }
  echo "$GODOT"; exit 0
fi
if command -v godot >/dev/null 2>&1 && version_ok godot; then
  command -v godot; exit 0
fi
if [[ -x "$wrapper" && -f "$marker" ]] && version_ok "$wrapper"; then
  echo "$wrapper"; exit 0
fi

# One fetch at a time: tools/demo.sh starts this beside the rest of the set-up, and the build asks
# again when it dumps the engine's interface; the second waits for the first and then finds its result.
mkdir -p "$(dirname "$cache")"
exec 8>"$cache.lock"
flock 8
if [[ -x "$wrapper" && -f "$marker" ]] && version_ok "$wrapper"; then
  echo "$wrapper"; exit 0
fi
echo "find_godot: fetching Godot 4 from Debian unstable into $cache" >&2
rm -rf "$cache"
mkdir -p "$cache"/apt/{lists/partial,cache/archives/partial,etc} "$cache/debs" "$cache/root"
echo 'deb [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian sid main' \
  > "$cache/apt/etc/sources.list"
: > "$cache/apt/status" # an empty dpkg status, so every dependency is resolved and fetched
apt_opts=(
  -o "Dir::Etc::SourceList=$cache/apt/etc/sources.list" -o "Dir::Etc::SourceParts=/nonexistent"
  -o "Dir::State::Lists=$cache/apt/lists" -o "Dir::Cache=$cache/apt/cache"
  -o "Dir::State::status=$cache/apt/status" -o "APT::Architecture=amd64" -o "APT::Architectures=amd64"
  -o "Debug::NoLocking=1" -o "APT::Sandbox::User=root"
)
apt-get "${apt_opts[@]}" -qq update >&2
# The library closure of the engine and of Mesa's Vulkan drivers (lavapipe renders without a GPU;
# Debian 12's own Mesa does not load into this newer C library); fonts and data-only packages are
# not needed to run it.
mapfile -t pkgs < <(apt-cache "${apt_opts[@]}" depends --recurse --no-recommends --no-suggests \
  --no-conflicts --no-breaks --no-replaces --no-enhances godot mesa-vulkan-drivers libvulkan1 2>/dev/null |
  grep -v '^ ' | grep -v '[<>]' | grep -Ev '^(fonts-|xfonts-|x11-common|sysvinit|lsb-base|cdebconf|debconf)' | sort -u)
(cd "$cache/debs" && apt-get "${apt_opts[@]}" -qq download "${pkgs[@]}" >&2)
for deb in "$cache"/debs/*.deb; do dpkg-deb -x "$deb" "$cache/root"; done
rm -rf "$cache/debs" "$cache/apt/cache"
root="$cache/root"
cat > "$wrapper" <<WRAP
#!/bin/sh
# Starts the unpacked Debian-unstable Godot through its own dynamic loader and libraries, with the
# Vulkan drivers unpacked beside it (unless the caller chose drivers).
r="$root"
if [ -z "\${VK_DRIVER_FILES:-}\${VK_ICD_FILENAMES:-}" ]; then
  VK_DRIVER_FILES=\$(ls "\$r"/usr/share/vulkan/icd.d/*.json | tr '\\n' ':')
  export VK_DRIVER_FILES
fi
exec "\$r/usr/lib64/ld-linux-x86-64.so.2" --library-path "\$r/usr/lib/x86_64-linux-gnu:\$r/lib/x86_64-linux-gnu:\$r/usr/lib/x86_64-linux-gnu/pulseaudio" "\$r/usr/bin/godot" "\$@"
WRAP
chmod +x "$wrapper"
version_ok "$wrapper" || { echo "find_godot: the fetched engine does not start" >&2; exit 1; }
touch "$marker"
echo "$wrapper"
