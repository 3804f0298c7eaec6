#!/usr/bin/env bash
# Build the manual (Sphinx, warnings as errors) and the API reference
# (Doxygen, problems in the comments as errors) into BUILD/manual:
#
#   scripts/manual.sh [BUILD]      BUILD defaults to build/ (its thinlayer
#                                  prints the parameter pages)
#
# The parameter pages are generated from `thinlayer --print-parameters`
# into a copy of doc/, so that they cannot drift from the program; the
# checkout is not written. Open BUILD/manual/html/index.html.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$top/build}" && pwd)"
out="$build/manual"
[ -x "$build/thinlayer" ] ||
  { echo "scripts/manual.sh: no program $build/thinlayer; build first (scripts/setup.sh build)" >&2; exit 1; }

rm -rf "$out/source" "$out/html"
mkdir -p "$out/source"
cp -R "$top/doc/." "$out/source/"
(cd "$top" && /usr/bin/python3 -m thinlayer_tools.manual.parameters "$build/thinlayer" \
   "$out/source/parameters")
/usr/bin/python3 -m sphinx -W --keep-going -q -b html "$out/source" "$out/html"
(cd "$top" && { cat doc/Doxyfile; echo "OUTPUT_DIRECTORY = $out/api"; } | doxygen -)
rm -rf "$out/html/api"
mv "$out/api/html" "$out/html/api"
echo "scripts/manual.sh: the manual is $out/html/index.html, the API reference $out/html/api/index.html"
