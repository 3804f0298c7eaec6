#!/usr/bin/env bash
# The paper's studies with their tables and figures, into output/.
#
#   scripts/run_studies.sh [case1|case2|case3|case4|all]     (default: all)
#
# The README (Reproducing the paper) gives what each takes.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$top"
thinlayer="$top/build/thinlayer"
plot="/usr/bin/python3 -m"  # run from the top folder: thinlayer_tools is importable
[ -x "$thinlayer" ] || { echo "build first: scripts/setup.sh run" >&2; exit 1; }
which="${1:-all}"

if [ "$which" = case1 ] || [ "$which" = all ]; then
  "$thinlayer" prm/case1-table1.prm
  $plot thinlayer_tools.plots.case1 table1 output/case1-table1
  "$thinlayer" prm/case1-figure3.prm
  $plot thinlayer_tools.plots.case1 figure3 output/case1-figure3
  for figure in figure4 figure5; do
    "$thinlayer" prm/case1-$figure.prm
    $plot thinlayer_tools.plots.case1 frictional output/case1-$figure
  done
  "$thinlayer" prm/case1-stability-map.prm
  $plot thinlayer_tools.plots.stability output/case1-stability-map
  for scene in case1-inclined-adhesive-zero-thickness case1-inclined-frictional-zero-thickness; do
    "$thinlayer" prm/$scene.prm
  done
  $plot thinlayer_tools.plots.interface output/case1-inclined-adhesive-zero-thickness
  "$thinlayer" prm/prandtl-strip-footing.prm
  $plot thinlayer_tools.plots.scene output/prandtl-strip-footing "(2 + pi) c" \
    --load-label "footing pressure / c" --displacement-label "settlement under the centre, w / b (b: half-width)" \
    --length-unit b
fi

if [ "$which" = case2 ] || [ "$which" = all ]; then
  for scene in case2-strip-footing case2-strip-footing-better-mesh case2-strip-footing-zero-thickness; do
    "$thinlayer" prm/$scene.prm
    $plot thinlayer_tools.plots.scene output/$scene "L C_w" --load-label "horizontal load / (L C_w)" \
      --displacement-label "footing displacement, E u / (C_w L)"
    $plot thinlayer_tools.plots.interface output/$scene
  done
  "$thinlayer" prm/case2-study.prm
  $plot thinlayer_tools.plots.study output/case2-study aspect_ratio
fi

if [ "$which" = case3 ] || [ "$which" = all ]; then
  for scene in case3-circular-footing case3-circular-footing-better-mesh case3-circular-footing-zero-thickness; do
    "$thinlayer" prm/$scene.prm
    $plot thinlayer_tools.plots.scene output/$scene "pi R^2 C_w" \
      --load-label "horizontal load / (pi R^2 C_w)" \
      --displacement-label "footing displacement, E u / (C_w R)" --length-unit R
    $plot thinlayer_tools.plots.interface output/$scene
  done
  "$thinlayer" prm/case3-study.prm
  $plot thinlayer_tools.plots.study output/case3-study Kinematics/Stations
fi

if [ "$which" = case4 ] || [ "$which" = all ]; then
  "$thinlayer" prm/case4-smooth-wall.prm
  "$thinlayer" prm/case4-rough-wall.prm
  $plot thinlayer_tools.plots.interface output/case4-smooth-wall
  $plot thinlayer_tools.plots.interface output/case4-rough-wall
  "$thinlayer" prm/case4-rough-wall-zero-thickness.prm
  $plot thinlayer_tools.plots.interface output/case4-rough-wall-zero-thickness
  "$thinlayer" prm/case4-figure12.prm
  $plot thinlayer_tools.plots.case4 output/case4-smooth-wall output/case4-figure12
  "$thinlayer" prm/case4-study.prm
  $plot thinlayer_tools.plots.study output/case4-study aspect_ratio
fi
echo "studies done: tables (*.md) and figures (*.png) are in output/*/"
echo "(scripts/reproduce.sh puts the paper's items beside these in one report)"
