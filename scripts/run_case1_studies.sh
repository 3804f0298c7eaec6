#!/usr/bin/env bash
# Griffiths' Case 1 studies: Table 1 and Figures 3, 4 and 5, with their
# tables and plots, into output/. About a minute on two cores.
#
#   scripts/run_case1_studies.sh
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$top"
thinlayer="$top/build/thinlayer"
[ -x "$thinlayer" ] || { echo "build first: scripts/setup.sh run" >&2; exit 1; }

"$thinlayer" prm/case1-table1.prm
/usr/bin/python3 scripts/plot_case1.py table1 output/case1-table1
"$thinlayer" prm/case1-figure3.prm
/usr/bin/python3 scripts/plot_case1.py figure3 output/case1-figure3
for figure in figure4 figure5; do
  "$thinlayer" prm/case1-$figure.prm
  /usr/bin/python3 scripts/plot_case1.py frictional output/case1-$figure
done
echo "Case 1 studies: output/case1-table1/table1.md and the PNG files in output/case1-*/"
