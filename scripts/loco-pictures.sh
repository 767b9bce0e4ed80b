#!/bin/bash
# Redraws the demo layout's locomotive pictures (resources/demo-layout/icons/*.png) from
# scripts/loco-pictures.cpp. Needs g++ and Qt 6 Gui (qt6-base-dev); the pictures are committed, so
# building Stellwerk never runs this.
set -euo pipefail
cd "$(dirname "$0")/.."
out=resources/demo-layout/icons
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck disable=SC2046
g++ -std=c++20 -O1 -fPIC scripts/loco-pictures.cpp -o "$tmp/loco-pictures" $(pkg-config --cflags --libs Qt6Gui)
mkdir -p "$out"
QT_QPA_PLATFORM=offscreen "$tmp/loco-pictures" "$out"
ls "$out"
