#!/bin/bash
# Draws the link graph of Stellwerk's libraries and programs (docs/graph/layers.svg) from the build's own
# target_link_libraries, so that the picture in docs/ARCHITECTURE.md is the build graph, not a wish.
# Usage: scripts/layer-graph.sh [BUILD_DIR]   (needs graphviz's `dot`; installs it when missing)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
if ! command -v dot > /dev/null; then
    sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get install -y -q graphviz
fi
[ -f "$build/CMakeCache.txt" ] || cmake -S "$root" -B "$build" > /dev/null
cp "$root/docs/graph/CMakeGraphVizOptions.cmake" "$build/"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$build" && cmake --graphviz="$work/stellwerk.dot" . > /dev/null)
# Without the legend; left to right reads like the layer table.
sed -e '/subgraph clusterLegend {/,/^}/d' -e 's/^digraph "Stellwerk" {/digraph "Stellwerk" {\n  rankdir = "BT";/' \
    "$work/stellwerk.dot" > "$root/docs/graph/layers.dot"
dot -Tsvg "$root/docs/graph/layers.dot" -o "$root/docs/graph/layers.svg"
echo "wrote docs/graph/layers.dot and docs/graph/layers.svg"
