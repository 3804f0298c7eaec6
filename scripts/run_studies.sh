#!/usr/bin/env bash
# The paper's studies with their tables and figures.
#
#   scripts/run_studies.sh [case1|case2|case3|case4|all] [OUTPUT]
#
# The studies go to OUTPUT/<scene> (default: "$out"/ in the checkout), each
# run by $THINLAYER (default: build/thinlayer, the Release build). The
# manual's page on the paper's cases gives what each computes.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
which="${1:-all}"
case "$which" in
  case1|case2|case3|case4|all) ;;
  *) echo "usage: $0 [case1|case2|case3|case4|all] [OUTPUT]" >&2; exit 2 ;;
esac
out="$(mkdir -p "${2:-$top/output}" && cd "${2:-$top/output}" && pwd)"
thinlayer="${THINLAYER:-$top/build/thinlayer}"
[ -x "$thinlayer" ] || { echo "no program $thinlayer: build first (scripts/setup.sh build)" >&2; exit 1; }
cd "$top"
plot="/usr/bin/python3 -m"  # run from the top folder: thinlayer_tools is importable
# A scene of prm/ into OUTPUT/<scene>.
run() { "$thinlayer" "prm/$1.prm" -s "Output/Directory=$out/$1"; }

if [ "$which" = case1 ] || [ "$which" = all ]; then
  run case1-table1
  $plot thinlayer_tools.plots.case1 table1 "$out"/case1-table1
  run case1-figure3
  $plot thinlayer_tools.plots.case1 figure3 "$out"/case1-figure3
  for figure in figure4 figure5; do
    run case1-$figure
    $plot thinlayer_tools.plots.case1 frictional "$out"/case1-$figure
  done
  run case1-stability-map
  $plot thinlayer_tools.plots.stability "$out"/case1-stability-map
  for scene in case1-inclined-adhesive-zero-thickness case1-inclined-frictional-zero-thickness; do
    run $scene
  done
  $plot thinlayer_tools.plots.profiles "$out"/case1-inclined-adhesive-zero-thickness
  run prandtl-strip-footing
  $plot thinlayer_tools.plots.scene "$out"/prandtl-strip-footing "(2 + pi) c" \
    --load-label "footing pressure / c" --displacement-label "settlement under the centre, w / b (b: half-width)" \
    --length-unit b
fi

if [ "$which" = case2 ] || [ "$which" = all ]; then
  for scene in case2-strip-footing case2-strip-footing-better-mesh case2-strip-footing-zero-thickness; do
    run $scene
    $plot thinlayer_tools.plots.scene "$out"/$scene "L C_w" --load-label "horizontal load / (L C_w)" \
      --displacement-label "footing displacement, E u / (C_w L)"
    $plot thinlayer_tools.plots.profiles "$out"/$scene
  done
  run case2-study
  $plot thinlayer_tools.plots.study "$out"/case2-study aspect_ratio
fi

if [ "$which" = case3 ] || [ "$which" = all ]; then
  for scene in case3-circular-footing case3-circular-footing-better-mesh case3-circular-footing-zero-thickness; do
    run $scene
    $plot thinlayer_tools.plots.scene "$out"/$scene "pi R^2 C_w" \
      --load-label "horizontal load / (pi R^2 C_w)" \
      --displacement-label "footing displacement, E u / (C_w R)" --length-unit R
    $plot thinlayer_tools.plots.profiles "$out"/$scene
  done
  run case3-study
  $plot thinlayer_tools.plots.study "$out"/case3-study Kinematics/Stations
fi

if [ "$which" = case4 ] || [ "$which" = all ]; then
  run case4-smooth-wall
  run case4-rough-wall
  $plot thinlayer_tools.plots.profiles "$out"/case4-smooth-wall
  $plot thinlayer_tools.plots.profiles "$out"/case4-rough-wall
  run case4-rough-wall-zero-thickness
  $plot thinlayer_tools.plots.profiles "$out"/case4-rough-wall-zero-thickness
  run case4-figure12
  $plot thinlayer_tools.plots.case4 "$out"/case4-smooth-wall "$out"/case4-figure12
  run case4-study
  $plot thinlayer_tools.plots.study "$out"/case4-study aspect_ratio
fi
echo "studies done: tables (*.md) and figures (*.png) are in "$out"/*/"
echo "(scripts/reproduce.sh puts the paper's items beside these in one report)"
