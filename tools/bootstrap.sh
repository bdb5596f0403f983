#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine: installs what is missing, builds, runs.
#   bash tools/bootstrap.sh demo      set up, build fair-curves, write the demo gallery to demo-out/
#   bash tools/bootstrap.sh serve     set up, build fair-curves, start the curve editor (fair-curves serve --open)
#   bash tools/bootstrap.sh test      set up, build everything, run every test (ctest)
#   bash tools/bootstrap.sh sanitize  the same tests built with -fsanitize=address,undefined
#   bash tools/bootstrap.sh bench     build and run the Google Benchmark programs
#   bash tools/bootstrap.sh setup     only install the Debian packages that are missing
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
jobs=${FAIR_JOBS:-$(nproc)}

packages=(build-essential cmake libcgal-dev libgmp-dev libmpfr-dev libboost-dev
          libgtest-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev libpng-dev)
# Test-only dependencies (never of the library): FreeType and Debian's DejaVu fonts for the glyph
# outlines of the real-data tests; OpenCASCADE's FairCurve_Batten (and the TBB its CMake config
# needs) as the peer of the optimal curves; python3-ezdxf, the independent reader of the DXF
# drawings (test/io_export/check_dxf.py).
test_packages=(libfreetype-dev fonts-dejavu-core libocct-modeling-algorithms-dev libocct-modeling-data-dev
               libocct-foundation-dev libtbb-dev python3-ezdxf)
# The Python module (python/, doc/python.md; -DFAIR_BUILD_PYTHON=ON in the test build) and its
# tests: pybind11 and numpy to build it, pytest and scipy (the independent oracle) to test it.
test_packages+=(python3-dev pybind11-dev python3-numpy python3-pytest python3-scipy)
# The editor's browser test (test/editor/browser_test.mjs, doc/editor.md): Debian's chromium,
# driven headless by puppeteer-core from npm (test/editor/package-lock.json; it never downloads a
# browser). Node.js and npm from Debian unless a node and an npm are already on the PATH (e.g.
# NodeSource's nodejs, which bundles npm and conflicts with Debian's npm package).
# Only for `test` (the sanitizer stage builds no program, hence no editor tests).
editor_test_packages=(chromium)
command -v node >/dev/null 2>&1 || editor_test_packages+=(nodejs)
command -v npm >/dev/null 2>&1 || editor_test_packages+=(npm)
# Benchmark-only: Eigen 3, the peer of bench_linear_algebra (doc/linear_algebra.md).
bench_packages=(libeigen3-dev)
# The sanitizer stage compiles with clang: its ASan+UBSan build of a CGAL test takes half the CPU
# time of GCC's (doc/benchmarks.md, "CI"); the runtimes are in libclang-rt-14-dev.
sanitize_packages=(clang libclang-rt-14-dev)

setup() {
  local missing=()
  for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "bootstrap: installing ${missing[*]}" >&2
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

configure() { # build-dir extra-cmake-args...
  local dir=$1; shift
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
}

case "${1:-}" in
  setup)
    setup ;;
  demo)
    setup
    configure build -DFAIR_BUILD_TESTS=OFF -DFAIR_BUILD_EXAMPLES=OFF
    cmake --build build --target fair-curves -j "$jobs"
    ./build/tools/fair-curves/fair-curves demo --out demo-out
    echo "bootstrap: open demo-out/index.html" ;;
  serve)
    setup
    configure build -DFAIR_BUILD_TESTS=OFF -DFAIR_BUILD_EXAMPLES=OFF
    cmake --build build --target fair-curves -j "$jobs"
    exec ./build/tools/fair-curves/fair-curves serve --open "${@:2}" ;;
  test)
    packages+=("${test_packages[@]}" "${editor_test_packages[@]}")
    setup
    # puppeteer-core at the locked version, no install scripts, never a browser download; the
    # browser test must then run (FAIR_EDITOR_REQUIRE_BROWSER: a missing tool fails it).
    (cd test/editor && PUPPETEER_SKIP_DOWNLOAD=1 npm ci --ignore-scripts --no-audit --no-fund --loglevel=error)
    export FAIR_EDITOR_REQUIRE_BROWSER=1
    # -O2 rather than Release's -O3: the tests, the program and the Python module of this build
    # compile in 17-21 % less CPU time (GCC 12, measured on test_classic_splines, test_kappa and
    # certify_command) and run within 10 % of its speed; the benchmarks (build-bench) keep -O3
    # (doc/benchmarks.md, "CI").
    configure build -DFAIR_BUILD_TESTS=ON -DFAIR_BUILD_EXAMPLES=ON -DFAIR_BUILD_PYTHON=ON \
      -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG"
    cmake --build build -j "$jobs"
    ctest --test-dir build --output-on-failure -j "$jobs" ;;
  sanitize)
    packages+=("${test_packages[@]}" "${sanitize_packages[@]}")
    setup
    # -g1: line tables only — enough for the sanitizers' file:line stack traces, and much less
    # debug information to generate and link for the CGAL templates than -g.
    # The tests of the code that owns memory, parses or solves, on one floating and one exact
    # kernel (test/CMakeLists.txt, FAIR_TESTS_NOT_SANITIZED; test/test_support.h), and the fuzz
    # corpora; not the program and the examples, which call that code and run in the release stage.
    configure build-sanitize -DCMAKE_CXX_COMPILER=clang++ -DFAIR_SANITIZE=ON -DFAIR_BUILD_TOOLS=OFF -DFAIR_BUILD_EXAMPLES=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1"
    cmake --build build-sanitize -j "$jobs"
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
      ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -E install_and_consume ;;
  bench)
    packages+=("${bench_packages[@]}")
    setup
    configure build-bench -DFAIR_BUILD_BENCHMARKS=ON -DFAIR_BUILD_TESTS=OFF -DFAIR_BUILD_EXAMPLES=OFF
    cmake --build build-bench -j "$jobs"
    for b in build-bench/benchmark/bench_*; do
      [ -x "$b" ] && "$b" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
    done ;;
  *)
    sed -n '2,8p' "$0" >&2
    exit 2 ;;
esac
