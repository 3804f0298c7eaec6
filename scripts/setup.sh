#!/usr/bin/env bash
# Set up thinlayer on Debian 12 and either run the main job or the tests.
#
#   scripts/setup.sh run    install what is missing, build (Release), run the
#                           paper's Case 1 to its collapse, compare it with
#                           the closed form, draw it, say where it all is
#   scripts/setup.sh build  install what is missing and build (Release) only
#                           (scripts/reproduce.sh starts with it)
#   scripts/setup.sh test   install what is missing, build (Release), run ctest;
#                           then build in Debug against deal.II's debug
#                           library and run ctest there (its assertions on),
#                           run five scenes under valgrind (memory errors
#                           fail the test), build the manual and the API
#                           reference (warnings fail), and reproduce the
#                           paper into its report (--quick) and open it in
#                           headless Chromium
#
# Re-running when nothing changed takes seconds: packages are installed only
# when missing, and the build is incremental. Needs root or sudo for apt.
set -euo pipefail

mode="${1:-run}"
case "$mode" in
  run|test|build) ;;
  *) echo "usage: $0 run|test|build" >&2; exit 2 ;;
esac

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$top/build"

# What the build, the tests and the plot scripts need, all from Debian.
# libopenblas0-serial replaces Debian's reference BLAS (through the
# alternatives system) under CHOLMOD's supernodal substitutions, which are
# then about 30% faster on the 2-core machine; serial, because the point loop
# already uses both cores. The reference outputs of the tests were made with
# it: a failed (non-converged) step's state depends on rounding.
# Ninja builds: ctest builds each test's program before it runs it, and
# Ninja finds a program up to date in a tenth of a second where make takes
# seconds.
# lld links the test programs in a third of gold's time.
packages=(g++ make cmake ninja-build perl libdeal.ii-dev gmsh numdiff python3 python3-matplotlib ccache
          lld libopenblas0-serial nlohmann-json3-dev valgrind procps openmpi-bin)
# The tests also read the fields with VTK's own readers, build the manual
# and the API reference, and open the reproduction report in a real browser.
if [ "$mode" = test ]; then
  packages+=(python3-vtk9 python3-sphinx python3-myst-parser doxygen chromium)
fi

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

# Configure (once) and build DIRECTORY as TYPE (Release or Debug), with
# further cmake options after them. The library is built in batches of
# source files (THINLAYER_UNITY_BUILD): from scratch about three times
# faster.
build_in() {
  local directory="$1" type="$2"
  shift 2
  mkdir -p "$directory"
  if [ ! -f "$directory/CMakeCache.txt" ]; then
    echo "thinlayer setup: configuring ($type) in $directory"
    cmake -G Ninja -S "$top" -B "$directory" -DCMAKE_BUILD_TYPE="$type" \
      -DTHINLAYER_UNITY_BUILD=ON "$@" \
      > "$directory/configure.log" 2>&1 ||
      { cat "$directory/configure.log"; echo "thinlayer setup: configuring failed" >&2; exit 1; }
  fi
  if ! cmake --build "$directory" -- -j"$(nproc)" > "$directory/build.log" 2>&1; then
    grep -E -B2 -A8 "error|Error" "$directory/build.log" | head -60
    echo "thinlayer setup: the build failed; the full log is $directory/build.log" >&2
    exit 1
  fi
}
build_in "$build" Release

# Every test program of DIRECTORY, ahead of ctest: each test would build
# its own, and the tests on several ranks run one at a time, their builds
# then holding one core of two.
build_test_programs() {
  if ! cmake --build "$1" --target thinlayer_test_programs -- -j"$(nproc)" \
       > "$1/build-tests.log" 2>&1; then
    grep -E -B2 -A8 "error|Error" "$1/build-tests.log" | head -60
    echo "thinlayer setup: building the test programs failed; the full log is $1/build-tests.log" >&2
    exit 1
  fi
}

if [ "$mode" = build ]; then
  echo "thinlayer setup: built $build/thinlayer"
elif [ "$mode" = run ]; then
  # The paper's Case 1 at 45 degrees: a column cut by an inclined Tresca
  # layer, loaded to collapse by the paper's method; its closed form is
  # P / (C_w B) = 1 / (sin(alpha) cos(alpha)) = 2.
  cd "$top"
  scene=case1-inclined-adhesive
  "$build/thinlayer" "prm/$scene.prm"
  labels=(--load-label "axial load P / (C_w B)" --displacement-label "settlement of the top / B")
  /usr/bin/python3 -m thinlayer_tools.plots.scene "output/$scene" "closed form 1 / (sin a cos a)" \
    "${labels[@]}"
  /usr/bin/python3 -m thinlayer_tools.first_run "output/$scene" "${labels[@]}" \
    --reference-label "closed form 1 / (sin a cos a)" --length-unit B
else
  # Each stage says how long it took: the whole is to stay within CI's
  # half hour.
  stage() { echo "thinlayer setup: $1 done at ${SECONDS} s"; }
  stage "the Release build"
  build_test_programs "$build"
  stage "the Release test programs"
  (cd "$build" && ctest --output-on-failure -j"$(nproc)")
  stage "the Release tests"
  echo "thinlayer setup: the manual (scripts/manual.sh)"
  "$top/scripts/manual.sh" "$build" > "$build/manual.log" 2>&1 ||
    { cat "$build/manual.log"; echo "thinlayer setup: the manual failed to build" >&2; exit 1; }
  stage "the manual"

  # The same tests against deal.II's debug library, where its assertions
  # (index ranges, vector sizes) run; built without debug information,
  # which the assertions do not need.
  debug="$top/build-debug"
  echo "thinlayer setup: building in Debug ($debug)"
  build_in "$debug" Debug -DTHINLAYER_DEBUG_INFORMATION=OFF
  stage "the Debug build"
  build_test_programs "$debug"
  stage "the Debug test programs"
  (cd "$debug" && ctest --output-on-failure -j"$(nproc)")
  stage "the Debug tests"

  # valgrind: a plane-strain scene (the default method, Newton included), a
  # Fourier one, one with zero-thickness interface elements (the mesh
  # split along a curve, Newton's singular tangent at the mechanism), one
  # under work control (Newton's bordered solve), and two 3D ones
  # (hexahedra, a layer's surface profile; a mesh split along a surface and
  # 16-node interface elements), with their VTU output.
  # Two lanes of about a minute each, side by side (one scene per core).
  mkdir -p "$build/valgrind"
  valgrind_scenes() {
    for scene in "$@"; do
      echo "thinlayer setup: valgrind on tests/scenes/$scene.prm"
      if ! valgrind -q --error-exitcode=99 "$build/thinlayer" "$top/tests/scenes/$scene.prm" \
           -s "Output/Directory=$build/valgrind/$scene" > "$build/valgrind/$scene.log" 2>&1; then
        grep -E "==[0-9]+==" "$build/valgrind/$scene.log" | head -40
        echo "thinlayer setup: valgrind found errors in $scene; the log is $build/valgrind/$scene.log" >&2
        return 1
      fi
    done
  }
  valgrind_scenes case1_3d_zero_thickness fourier_cylinder_plastic case2_work_control &
  lane_a=$!
  valgrind_scenes case1_3d_default case2_default_thin case2_zero_thickness &
  lane_b=$!
  valgrind_failed=0
  wait "$lane_a" || valgrind_failed=1
  wait "$lane_b" || valgrind_failed=1
  [ "$valgrind_failed" -eq 0 ] || exit 1
  stage "valgrind"
  # The paper reproduced into its report (--quick: smaller sweeps, the
  # benchmark run once), and the page checked in headless Chromium.
  echo "thinlayer setup: scripts/reproduce.sh --quick"
  report="$build/reproduce-quick"
  "$top/scripts/reproduce.sh" --quick --jobs "$(nproc)" --output "$report" 2>&1 |
    tee "$build/reproduce-quick.log" ||
    { echo "thinlayer setup: the reproduction failed; the log is $build/reproduce-quick.log" >&2
      exit 1; }
  PYTHONPATH="$top" /usr/bin/python3 -m thinlayer_tools.report.check "$report/report.html"
  stage "the reproduction"
  echo "thinlayer setup: all tests passed (Release, the manual, Debug, valgrind, the report in Chromium)"
fi
