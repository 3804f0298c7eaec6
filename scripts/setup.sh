#!/usr/bin/env bash
# Set up thinlayer on Debian 12 and either run the main job or the tests.
#
#   scripts/setup.sh run    install what is missing, build (Release), run the
#                           default scene and say where its results are
#   scripts/setup.sh test   install what is missing, build (Release), run ctest
#
# Re-running when nothing changed takes seconds: packages are installed only
# when missing, and the build is incremental. Needs root or sudo for apt.
set -euo pipefail

mode="${1:-run}"
case "$mode" in
  run|test) ;;
  *) echo "usage: $0 run|test" >&2; exit 2 ;;
esac

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$top/build"

# What the build, the tests and the plot scripts need, all from Debian.
# libopenblas0-serial replaces Debian's reference BLAS (through the
# alternatives system) under CHOLMOD's supernodal substitutions, which are
# then about 30% faster on the 2-core machine; serial, because the point loop
# already uses both cores. The reference outputs of the tests were made with
# it: a failed (non-converged) step's state depends on rounding.
packages=(g++ make cmake perl libdeal.ii-dev gmsh numdiff python3 python3-matplotlib ccache libopenblas0-serial
          nlohmann-json3-dev)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "thinlayer setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
fi

mkdir -p "$build"
if [ ! -f "$build/CMakeCache.txt" ]; then
  echo "thinlayer setup: configuring (Release) in $build"
  cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release > "$build/configure.log" 2>&1 ||
    { cat "$build/configure.log"; echo "thinlayer setup: configuring failed" >&2; exit 1; }
fi
if ! cmake --build "$build" -- -j"$(nproc)" > "$build/build.log" 2>&1; then
  grep -E -B2 -A8 "error|Error" "$build/build.log" | head -60
  echo "thinlayer setup: the build failed; the full log is $build/build.log" >&2
  exit 1
fi

if [ "$mode" = run ]; then
  cd "$top"
  "$build/thinlayer" prm/case1-elastic.prm
  echo "thinlayer setup: open $top/output/case1-elastic/fields.pvd in ParaView;"
  echo "  history.csv and summary.json are beside it."
else
  cd "$build"
  ctest --output-on-failure -j"$(nproc)"
fi
