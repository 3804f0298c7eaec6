#!/usr/bin/env bash
# Reproduce Griffiths' paper into one self-contained HTML report.
#
#   scripts/reproduce.sh [--quick] [--output DIR] [--jobs N]
#
# Installs what is missing and builds (Release) as scripts/setup.sh does,
# then runs every scene of the paper's tables and figures, by the paper's
# method and by the default one, the validations, the stability maps and
# the speed-against-accuracy benchmark, and writes DIR/report.html (default
# output/reproduce/report.html; DIR is replaced when the page is written,
# so an error leaves the previous reproduction). Progress is printed
# run by run. --quick: smaller sweeps and a benchmark run once (for CI).
# --jobs N: N scenes on one rank at a time (default 1; the benchmarks, the
# scaling runs and the runs on several ranks always run alone).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
arguments=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) arguments+=(--quick) ;;
    --output) [ $# -ge 2 ] || { echo "usage: $0 [--quick] [--output DIR] [--jobs N]" >&2; exit 2; }
              arguments+=(--output "$2"); shift ;;
    --jobs) [ $# -ge 2 ] || { echo "usage: $0 [--quick] [--output DIR] [--jobs N]" >&2; exit 2; }
            arguments+=(--jobs "$2"); shift ;;
    -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: $0 [--quick] [--output DIR] [--jobs N]" >&2; exit 2 ;;
  esac
  shift
done
"$top/scripts/setup.sh" build
# The Python package thinlayer_tools lives in the top folder.
export PYTHONPATH="$top${PYTHONPATH:+:$PYTHONPATH}"
exec /usr/bin/python3 -m thinlayer_tools.reproduce "${arguments[@]}"
