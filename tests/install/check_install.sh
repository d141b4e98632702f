#!/usr/bin/env bash
# An installed flexmoor works away from its source and build trees (run by ctest as Install.Tree):
#   bash check_install.sh BUILD_DIR SOURCE_DIR
# 1. `cmake --install BUILD_DIR --prefix P` into a temporary P lays out bin/, lib/ (libflexmoor
#    with its SONAME and links), include/flexmoor/, the CMake package, flexmoor.pc,
#    share/flexmoor/{cases,plot} (every case and data file of cases/, every script of apps/plot)
#    and share/doc/flexmoor; the library and the command hold no path into SOURCE_DIR's data.
# 2. From a folder outside both trees, with neither FLEXMOOR_DATA_DIR nor LD_LIBRARY_PATH set,
#    P/bin/flexmoor loads P's libflexmoor, lists every named case and runs ex8-relaxation-test.
# 3. FLEXMOOR_DATA_DIR points the lookup elsewhere; with the data gone and no variable, the
#    command says which folder it searched.
# 4. A project outside the tree (consumer/) builds against P with find_package(flexmoor) and
#    again with pkg-config, and both programs run the case in process and print the command's
#    summary values.
# 5. The C example host (examples/c/platform_host.c) builds as C99 against P's flexmoor.h with
#    pkg-config and runs OC4 for 2 s; P's Python module imports and runs Example 8.
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
unset FLEXMOOR_DATA_DIR LD_LIBRARY_PATH

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }
expect_file() { [ -f "$prefix/$1" ] || fail "no $1 in the installed tree"; }

# 1. The installed tree.
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/flexmoor lib/libflexmoor.so.0.1.0 include/flexmoor/libstruct/model/model.hpp \
         include/flexmoor/libhydro/waves/dispersion.hpp include/flexmoor/apps/case/case_reader.hpp \
         include/flexmoor/apps/run/simulation.hpp lib/cmake/flexmoor/flexmoorConfig.cmake \
         lib/cmake/flexmoor/flexmoorConfigVersion.cmake lib/cmake/flexmoor/flexmoorTargets.cmake \
         lib/pkgconfig/flexmoor.pc share/doc/flexmoor/README.md share/doc/flexmoor/LICENSE \
         share/doc/flexmoor/docs/tutorial.md; do
  expect_file "$f"
done
[ "$(readlink "$prefix/lib/libflexmoor.so")" = libflexmoor.so.0 ] ||
  fail "libflexmoor.so is not a link to libflexmoor.so.0"
[ "$(readlink "$prefix/lib/libflexmoor.so.0")" = libflexmoor.so.0.1.0 ] ||
  fail "libflexmoor.so.0 is not a link to libflexmoor.so.0.1.0"
# (grep reads a variable, not a pipe: with pipefail, grep -q quitting early would fail the pipe)
dynamic=$(readelf -d "$prefix/lib/libflexmoor.so.0.1.0")
grep -q 'SONAME.*\[libflexmoor\.so\.0\]' <<<"$dynamic" || fail "the SONAME is not libflexmoor.so.0"
dynamic=$(readelf -d "$prefix/bin/flexmoor")
grep -q 'R.*PATH.*\[\$ORIGIN/\.\./lib\]' <<<"$dynamic" ||
  fail "bin/flexmoor's run path is not \$ORIGIN/../lib"
if [ -f "$build/bin/libflexmoor_mpi.so" ]; then expect_file bin/libflexmoor_mpi.so; fi
if [ -f "$source/apps/capi/flexmoor.h" ]; then
  expect_file include/flexmoor.h
  expect_file include/flexmoor/apps/capi/flexmoor.h
fi
(cd "$source" && find cases -type f) | while read -r f; do
  [ -f "$prefix/share/flexmoor/$f" ] || echo "FAILED: no share/flexmoor/$f in the installed tree"
done | tee "$work/missing-cases"
[ -s "$work/missing-cases" ] && failures=$((failures + 1))
for f in "$source"/apps/plot/*.py; do expect_file "share/flexmoor/plot/$(basename "$f")"; done
(cd "$source" && find libstruct libhydro apps -name '*.hpp') | while read -r f; do
  [ -f "$prefix/include/flexmoor/$f" ] ||
    echo "FAILED: no include/flexmoor/$f in the installed tree"
done | tee "$work/missing-headers"
[ -s "$work/missing-headers" ] && failures=$((failures + 1))
for binary in lib/libflexmoor.so.0.1.0 bin/flexmoor; do
  if grep -aqF -e "$source/cases" -e "$source/apps/plot" "$prefix/$binary"; then
    fail "$binary holds a path into $source's cases/ or apps/plot/"
  fi
done

# 2. The installed command, from outside both trees.
mkdir "$work/elsewhere"
cd "$work/elsewhere"
loaded=$(ldd "$prefix/bin/flexmoor")
grep -qF "libflexmoor.so.0 => $prefix/bin/../lib/libflexmoor.so.0" <<<"$loaded" ||
  fail "bin/flexmoor does not load $prefix/lib's libflexmoor: $(grep libflexmoor <<<"$loaded")"
"$prefix/bin/flexmoor" cases >"$work/cases.txt" || fail "flexmoor cases exited $?"
listed=$(wc -l <"$work/cases.txt")
shipped=$(find "$source/cases" -name '*.yaml' | wc -l)
[ "$listed" -eq "$shipped" ] || fail "flexmoor cases listed $listed cases (expected $shipped)"
grep -q '^ex8-relaxation-test ' "$work/cases.txt" ||
  fail "flexmoor cases does not list ex8-relaxation-test"
"$prefix/bin/flexmoor" run ex8-relaxation-test --no-figure -o "$work/run" >"$work/run.log" 2>&1 ||
  fail "flexmoor run ex8-relaxation-test exited $?: $(cat "$work/run.log")"
summary=$work/run/ex8-relaxation-test.summary.json
[ -f "$work/run/ex8-relaxation-test.nc" ] && [ -f "$summary" ] ||
  fail "flexmoor run left no .nc or .summary.json"

# 3. FLEXMOOR_DATA_DIR, and the message when the data are missing.
mkdir -p "$work/data/cases"
cp "$prefix/share/flexmoor/cases/seed/ex8-relaxation-test.yaml" "$work/data/cases/only-case.yaml"
[ "$(FLEXMOOR_DATA_DIR=$work/data "$prefix/bin/flexmoor" cases | cut -d' ' -f1)" = only-case ] ||
  fail "flexmoor cases under FLEXMOOR_DATA_DIR=$work/data does not list its one case"
mv "$prefix/share/flexmoor" "$prefix/share/flexmoor-away"
code=0
"$prefix/bin/flexmoor" cases >/dev/null 2>"$work/missing.txt" || code=$?
[ "$code" -ne 0 ] && grep -qF "$prefix/share/flexmoor/cases" "$work/missing.txt" ||
  fail "without its data, flexmoor cases (exit $code) does not name the folder searched:" \
       "$(cat "$work/missing.txt")"
mv "$prefix/share/flexmoor-away" "$prefix/share/flexmoor"

# 4. A project that uses the installed library.
cmake -S "$here/consumer" -B "$work/consumer-build" -DCMAKE_PREFIX_PATH="$prefix" \
      >"$work/consumer.log" 2>&1 &&
  cmake --build "$work/consumer-build" >>"$work/consumer.log" 2>&1 ||
  fail "the consumer project did not build with find_package(flexmoor): $(cat "$work/consumer.log")"
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
# shellcheck disable=SC2046  # pkg-config's flags are words
g++ -std=c++17 -o "$work/consumer-pc" "$here/consumer/main.cpp" "$here/consumer/headers.cpp" \
    $(pkg-config --cflags --libs flexmoor) -Wl,-rpath,"$prefix/lib" >"$work/pc.log" 2>&1 ||
  fail "the consumer did not build with pkg-config: $(cat "$work/pc.log")"
expected=$(/usr/bin/python3 -c 'import json, sys
r = json.load(open(sys.argv[1]))["results"]
print("\n".join(f"{k} {v!r}" for k, v in r.items() if k != "cpu_seconds"))' "$summary")
for program in "$work/consumer-build/consumer" "$work/consumer-pc"; do
  [ -x "$program" ] || continue
  printed=$("$program" ex8-relaxation-test | grep -v '^cpu_seconds ') || fail "$program exited $?"
  same=$(/usr/bin/python3 -c 'import sys
a = [l.split() for l in sys.argv[1].splitlines()]
b = [l.split() for l in sys.argv[2].splitlines()]
close = lambda x, y: abs(float(x) - float(y)) <= 1e-12 * max(1.0, abs(float(y)))
print(len(a) > 0 and [k for k, _ in a] == [k for k, _ in b] and
      all(close(x, y) for (_, x), (_, y) in zip(a, b)))' \
    "$printed" "$expected")
  [ "$same" = True ] ||
    fail "$program printed '$printed' (expected the command's summary '$expected')"
done

# 5. The C example host built as C99 against the installed C interface (flexmoor.h) with
#    pkg-config, and the installed Python module, each running a case from the installed data.
# shellcheck disable=SC2046  # pkg-config's flags are words
cc -std=c99 -o "$work/platform_host" "$source/examples/c/platform_host.c" \
   $(pkg-config --cflags --libs flexmoor) -lm -Wl,-rpath,"$prefix/lib" >"$work/host.log" 2>&1 ||
  fail "the C example did not build against the installed flexmoor.h: $(cat "$work/host.log")"
if [ -x "$work/platform_host" ]; then
  (cd "$work" && ./platform_host oc4-semi-surge -o host --duration 2 >host-run.log 2>&1) ||
    fail "the installed C example failed: $(cat "$work/host-run.log")"
  [ -f "$work/host/oc4-semi-surge.nc" ] || fail "the installed C example wrote no results"
fi
if [ -d "$prefix/lib/python3/dist-packages" ]; then
  printed=$(cd "$work" && PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c '
import flexmoor
summary = flexmoor.Simulation("ex8-relaxation-test").run()
print(flexmoor.__file__, len(summary))' 2>&1) ||
    fail "the installed Python module failed: $printed"
  case "$printed" in
    "$prefix/lib/python3/dist-packages/"*) ;;
    *) fail "python imported another flexmoor module: $printed" ;;
  esac
fi

if [ "$failures" -ne 0 ]; then
  echo "install check: $failures failure(s)"
  exit 1
fi
echo "install check: the installed tree, the command, FLEXMOOR_DATA_DIR, find_package," \
     "pkg-config, the C example and the Python module all work"
