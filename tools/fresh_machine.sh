#!/usr/bin/env bash
# Times one of the README's commands on a fresh machine: a new Debian 12 root (debootstrap's minbase,
# plus git, with which a user clones), no ~/.cache, none of the packages the set-up installs, a new
# clone of this repository's HEAD; entered with chroot, as root, with no display.
#   tools/fresh_machine.sh demo        # tools/demo.sh
#   tools/fresh_machine.sh test        # CI=true bash .ci/run (tools/test.sh)
# Needs root, debootstrap (apt-get install debootstrap) and the network to the Debian mirror this
# machine's apt uses. The machine's own set-up that is not ours is carried into the root: its DNS,
# its apt sources and settings, its extra certificate authorities and pip's settings (a sandbox's
# egress proxy, say). Prints "fresh machine: <command> rc=N wall=S s"; the command's output is in
# <root>/root/run.log. The root (default /srv/sunflower_fresh, FRESH_ROOT to change) is made anew.
set -euo pipefail

what=${1:-}
case "$what" in
  demo) command="tools/demo.sh" ;;
  test) command="CI=true bash .ci/run" ;;
  *) echo "usage: tools/fresh_machine.sh demo|test" >&2; exit 2 ;;
esac
[[ $(id -u) == 0 ]] || { echo "fresh_machine: needs root (debootstrap, chroot, mounts)" >&2; exit 1; }
command -v debootstrap >/dev/null || { echo "fresh_machine: needs debootstrap (apt-get install debootstrap)" >&2; exit 1; }
repo=$(cd "$(dirname "$0")/.." && pwd)
root=${FRESH_ROOT:-/srv/sunflower_fresh}
mirror=$(sed -n 's/^URIs: *//p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -n 1)
mirror=${mirror:-http://deb.debian.org/debian}

unmount() { for d in dev sys proc; do umount -R "$root/$d" 2>/dev/null || true; done; }
trap unmount EXIT
unmount
rm -rf "$root"
echo "fresh_machine: a new Debian 12 root in $root (from $mirror)"
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
  { echo "fresh_machine: debootstrap failed (see $root.debootstrap.log)" >&2; exit 1; }
cp /etc/resolv.conf "$root/etc/"
if [[ -f /etc/apt/sources.list.d/debian.sources ]]; then
  cp /etc/apt/sources.list.d/debian.sources "$root/etc/apt/sources.list.d/"
  rm -f "$root/etc/apt/sources.list"
fi
for conf in /etc/apt/apt.conf.d/99*; do [[ -f $conf ]] && cp "$conf" "$root/etc/apt/apt.conf.d/"; done
mkdir -p "$root/usr/local/share/ca-certificates"
cp /usr/local/share/ca-certificates/*.crt "$root/usr/local/share/ca-certificates/" 2>/dev/null || true
[[ -f /etc/pip.conf ]] && cp /etc/pip.conf "$root/etc/"
git clone -q "$repo" "$root/root/sunflower"
mount -t proc proc "$root/proc"
mount --rbind /sys "$root/sys"
mount --rbind /dev "$root/dev"
inside() { chroot "$root" /usr/bin/env -i HOME=/root TERM=dumb PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin bash -c "$1"; }
inside "apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends git >/dev/null 2>&1"
echo "fresh_machine: running '$command' in the new clone"
start=$(date +%s)
rc=0
inside "cd /root/sunflower && $command" >"$root/root/run.log" 2>&1 || rc=$?
echo "fresh machine: $command rc=$rc wall=$(($(date +%s) - start)) s"
tail -n 3 "$root/root/run.log"
exit $rc
