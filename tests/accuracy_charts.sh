#!/bin/sh
# Regenerates the charts of docs/accuracy.md: one `drt bench` per example scene,
# then the PNG charts and the summaries copied into docs/images/accuracy/.
#
#   tests/accuracy_charts.sh [DRT [WORK]]
#     DRT   the drt executable (default: build/drt)
#     WORK  where the bench folders go (default: /tmp/drt-accuracy); references
#           there are reused by later runs while the scene is unchanged.
#
# Settings are small on purpose (48x36 pixels, 1-64 spp, 3 seeds, one thread so
# that timings do not depend on how busy the other core is): under a minute
# on a 2-core machine, less when the references already exist.
# Scenes that are missing are reported and skipped. A filter method equal to
# the scene's own filter is skipped by drt bench (the sobol method renders it).
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
DRT=${1:-$ROOT/build/drt}
WORK=${2:-/tmp/drt-accuracy}
OUT=$ROOT/docs/images/accuracy
COMMON="--width 48 --height 36 --spp 1,4,16,64 --seeds 3 --reference-spp 1024 --threads 1"
SAMPLERS=independent,stratified,sobol,adaptive
LIGHTS=light-grid,light-stratified,light-solid-angle
FILTERS=filter-box,filter-tent,filter-gaussian
mkdir -p "$OUT"

bench() { # scene methods
    if [ ! -f "$ROOT/examples/$1.drt" ]; then
        echo "accuracy_charts: examples/$1.drt is missing: skipped" >&2
        return
    fi
    # shellcheck disable=SC2086
    "$DRT" bench "$ROOT/examples/$1.drt" -o "$WORK/$1" $COMMON --methods "$2"
    cp "$WORK/$1/error-vs-time.png" "$OUT/$1-error-vs-time.png"
    cp "$WORK/$1/error-vs-spp.png" "$OUT/$1-error-vs-spp.png"
    cp "$WORK/$1/summary.md" "$OUT/$1-summary.md"
}

bench anti_aliasing "$SAMPLERS,$FILTERS"
bench depth_of_field "$SAMPLERS,$LIGHTS"
bench motion_blur "$SAMPLERS"
bench soft_shadows "$SAMPLERS,$LIGHTS"
bench glossy "$SAMPLERS"
bench translucency "$SAMPLERS"
bench cook "$SAMPLERS,$LIGHTS"
