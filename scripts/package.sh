#!/usr/bin/env bash
# Makes the .deb from the build in build/ (scripts/setup.sh builds it first when there is none) and checks
# it as a fresh machine would use it: the package's dependencies resolve (apt-get, simulated), its desktop
# entry and AppStream metadata validate, and the programs start from a scratch root the package was
# unpacked into, far from the build tree: stellwerk-cli --version, stellwerk-sim --help, and the desktop
# app offscreen on its simulated station (a screenshot once it is ready).
#
#   scripts/package.sh          leaves build/stellwerk_<version>_<arch>.deb
set -euo pipefail

# shellcheck source=common.sh
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/common.sh"
cd "$(dirname "${BASH_SOURCE[0]}")/.."

install_packages dpkg-dev desktop-file-utils appstream file
[[ -f build/CMakeCache.txt ]] || bash scripts/setup.sh
cmake --build build -j"$(nproc)" --target stellwerk stellwerk-cli stellwerk-sim

say "Making the package"
rm -f build/stellwerk_*.deb
(cd build && cpack -G DEB >/dev/null)
deb=$(ls build/stellwerk_*.deb)
dpkg-deb --info "$deb" | sed -n 's/^ \(Package\|Version\|Depends\):/  \1:/p'

say "Checking that its dependencies resolve"
apt-get install --simulate -q "./$deb" >/dev/null 2>&1 || apt-get install --simulate "./$deb" ||
    fail "the package's dependencies do not resolve"

root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
dpkg-deb -x "$deb" "$root"
say "Unpacked into $root"
for path in usr/bin/stellwerk usr/bin/stellwerk-cli usr/bin/stellwerk-sim \
    usr/share/applications/io.github.stellwerk.Stellwerk.desktop \
    usr/share/metainfo/io.github.stellwerk.Stellwerk.metainfo.xml \
    usr/share/icons/hicolor/scalable/apps/io.github.stellwerk.Stellwerk.svg \
    usr/share/doc/stellwerk/README.md usr/share/doc/stellwerk/guide/README.md; do
    [[ -e "$root/$path" ]] || fail "the package lacks /$path"
done
dynamic=$(readelf -d "$root/usr/bin/stellwerk")
[[ $dynamic != *RPATH* && $dynamic != *RUNPATH* ]] ||
    fail "the installed program carries a library run path (it must need none)"


say "Validating the desktop entry and the AppStream metadata"
desktop-file-validate "$root/usr/share/applications/io.github.stellwerk.Stellwerk.desktop"
appstreamcli validate --no-net "$root/usr/share/metainfo/io.github.stellwerk.Stellwerk.metainfo.xml"

say "Starting the installed programs"
"$root/usr/bin/stellwerk-cli" --version
"$root/usr/bin/stellwerk-sim" --help >/dev/null
mkdir -p "$root/home"
shot="$root/home/first-start.png"
XDG_CONFIG_HOME="$root/home" QT_QPA_PLATFORM=offscreen timeout 120 \
    "$root/usr/bin/stellwerk" --simulated --screenshot "$shot"
[[ $(file -b "$shot") == PNG* ]] || fail "the installed app did not show its window"
say "The package works: $deb"
