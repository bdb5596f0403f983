#!/usr/bin/env bash
# Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
#
# tools/check_headers.sh: the header hygiene of include/fair (issue 23, sections 1 and 3), as
# one check that ctest runs (test name `header_hygiene`):
#   1. no file under include/ is above 600 lines (one concept per file, readable by a newcomer);
#   2. no public header (include/fair/*.h, include/fair/io/*.h) opens namespace internal: the
#      algorithms live in include/fair/internal/<part>/ (io: include/fair/io/internal/), the
#      public header holds the class, its vocabulary and its contract only;
#   3. no #include cycle among the headers of include/fair (a cycle through internal files
#      counts too: a public header must be includable first, whatever else was included);
#   4. every public header compiles on its own: a translation unit holding only
#      `#include <fair/X.h>` passes `-fsyntax-only -Werror` (it includes what it uses).
# Every violation is printed; the exit status is 1 if there is any, 0 otherwise.
#
# Usage: tools/check_headers.sh [--cxx COMPILER] [--jobs N] [--allow-internal HEADER]...
#                               [SOURCE_DIR] [-- EXTRA_COMPILER_FLAGS...]
#   SOURCE_DIR       the repository root (default: the parent of this script's folder);
#   --cxx            the C++ compiler (default: $CXX, else c++);
#   --jobs           parallel compilations for check 4 (default 2);
#   --allow-internal a public header (path relative to include/, e.g. fair/Errors.h) exempt
#                    from check 2; the exemption is named in the output, so it stays visible;
#   --allow-cycle    a header (path relative to include/) whose include cycles are exempt from
#                    check 3 (the public-header-then-internal-definitions pattern); named in the
#                    output, so it stays visible;
#   --skip-compile   checks 1-3 only (they take well under a second).
# The flags after `--` are added to every compilation (e.g. -isystem for a dependency outside
# the default search path).

set -uo pipefail

max_lines=600
cxx=${CXX:-c++}
jobs=2
compile=1
allowed=()
allowed_cycles=()
src=
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --cxx) cxx=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --allow-internal) allowed+=("$2"); shift 2 ;;
    --allow-cycle) allowed_cycles+=("$2"); shift 2 ;;
    --skip-compile) compile=0; shift ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,29p' "$0"; exit 0 ;;
    -*) echo "check_headers: unknown option $1" >&2; exit 2 ;;
    *) src=$1; shift ;;
  esac
done
[ -n "$src" ] || src=$(cd "$(dirname "$0")/.." && pwd)
inc=$src/include
[ -d "$inc/fair" ] || { echo "check_headers: no $inc/fair" >&2; exit 2; }
cd "$inc" || exit 2

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

mapfile -t all_headers < <(find fair -type f \( -name '*.h' -o -name '*.hpp' \) | LC_ALL=C sort)
mapfile -t public_headers < <(find fair fair/io -maxdepth 1 -type f -name '*.h' | LC_ALL=C sort -u)

# ---------------------------------------------------------------- 1. file length
while read -r n f; do
  [ "$f" = total ] && continue
  [ "$n" -le "$max_lines" ] || fail "include/$f has $n lines (at most $max_lines)"
done < <(wc -l "${all_headers[@]}")

# ---------------------------------------------------------------- 2. internal code in public headers
internal_opening='^[[:space:]]*(inline[[:space:]]+)?namespace[[:space:]]+([A-Za-z_:]*::)?internal([[:space:]]|\{|::|$)'
is_allowed() {
  local a
  for a in "${allowed[@]+"${allowed[@]}"}"; do [ "$a" = "$1" ] && return 0; done
  return 1
}
# An opening of the namespace (`namespace internal {`, `namespace fair::internal::x {`), not a
# using-directive (`using namespace internal::parametric;`) or a qualified name.
mapfile -t offenders < <(grep -lE "$internal_opening" "${public_headers[@]}")
for f in "${offenders[@]+"${offenders[@]}"}"; do
  hits=$(grep -nE "$internal_opening" "$f")
  if is_allowed "$f"; then
    echo "allowed: include/$f opens namespace internal (exempted by --allow-internal)"
  else
    fail "include/$f opens namespace internal (move the code to include/fair/internal/<part>/ or include/fair/io/internal/):"
    echo "$hits" | sed 's/^/      /'
  fi
done

# ---------------------------------------------------------------- 3. include cycles
declare -A edges state
# Only the library's own headers, in the form the library uses: #include <fair/...>.
while read -r f g; do
  edges[$f]+="$g "
done < <(awk 'match($0, /^[ \t]*#[ \t]*include[ \t]*[<"]fair\/[^>"]+/) {
                s = substr($0, RSTART, RLENGTH); sub(/^[^<"]*[<"]/, "", s); print FILENAME, s }' "${all_headers[@]}")
for f in "${all_headers[@]}"; do
  for g in ${edges[$f]:-}; do
    [ -f "$g" ] || fail "include/$f includes <$g>, which does not exist"
  done
done
# Iterative depth-first search (0 new, 1 on the stack, 2 done); a back edge is a cycle.
cycles=0
for root in "${all_headers[@]}"; do
  [ "${state[$root]:-0}" = 0 ] || continue
  stack=("$root")
  next=(0)
  state[$root]=1
  while [ ${#stack[@]} -gt 0 ]; do
    top=$((${#stack[@]} - 1))
    v=${stack[$top]}
    read -r -a out <<< "${edges[$v]:-}"
    i=${next[$top]}
    if [ "$i" -ge "${#out[@]}" ]; then
      state[$v]=2
      unset 'stack[top]' 'next[top]'
      stack=("${stack[@]+"${stack[@]}"}")
      next=("${next[@]+"${next[@]}"}")
      continue
    fi
    next[$top]=$((i + 1))
    w=${out[$i]}
    [ -f "$w" ] || continue
    case "${state[$w]:-0}" in
      0) state[$w]=1; stack+=("$w"); next+=(0) ;;
      1) # w is on the stack: the cycle is w -> ... -> v -> w
         path=""
         on=0
         for s in "${stack[@]}"; do
           [ "$s" = "$w" ] && on=1
           [ $on = 1 ] && path+="$s -> "
         done
         exempt=0
         for a in "${allowed_cycles[@]+"${allowed_cycles[@]}"}"; do
           case " ${path}$w " in *"$a "*) exempt=1 ;; esac
         done
         if [ $exempt = 1 ]; then
           echo "allowed: include cycle ${path}$w (exempted by --allow-cycle)"
         else
           fail "include cycle: ${path}$w"
         fi
         cycles=$((cycles + 1)) ;;
    esac
  done
done

# ---------------------------------------------------------------- 4. every public header on its own
if [ "$compile" = 1 ]; then
  flags=(-x c++ -std=c++17 -fsyntax-only -Werror -Wall -Wextra -Wpedantic -frounding-math
         -DCGAL_USE_GMPXX=1 -I"$inc" "${extra[@]+"${extra[@]}"}")
  logs=$(mktemp -d)
  trap 'rm -rf "$logs"' EXIT
  export cxx logs
  export flags_string
  flags_string=$(printf '%q ' "${flags[@]}")
  printf '%s\n' "${public_headers[@]}" | xargs -P "$jobs" -I{} bash -c '
    h={}
    log=$logs/$(echo "$h" | tr / _).log
    eval "f=($flags_string)"
    if ! printf "#include <%s>\n" "$h" | "$cxx" "${f[@]}" - > "$log" 2>&1; then
      echo failed >> "$log.status"
    fi'
  for h in "${public_headers[@]}"; do
    log=$logs/$(echo "$h" | tr / _).log
    if [ -f "$log.status" ]; then
      fail "include/$h does not compile on its own ($cxx -fsyntax-only):"
      head -n 20 "$log" | sed 's/^/      /'
    fi
  done
fi

echo "check_headers: ${#all_headers[@]} headers, ${#public_headers[@]} public, $failures failure(s)"
[ "$failures" = 0 ]
