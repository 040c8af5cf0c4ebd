#!/usr/bin/env bash
# The C ABI's checks (issues 27 and 37), run by .ci/run: the committed header is the one cbindgen
# generates now; the static and shared libraries build (the shared one with its soname); the
# header compiles with -Wall -Wextra -Werror -pedantic as C99, C11, C17, C++11 and C++17; the C
# tests and the example, compiled by the system's C compiler with -Wall -Wextra -Werror and
# linked with the static library, pass under valgrind (memcheck, --error-exitcode=1):
#   tests/layout.c        every struct's size, alignment and field offsets (_Static_assert);
#   tests/status.c        every status code, the IEC timers' structure operations, the memory
#                         areas' STL operations, the BCD preset entries;
#   tests/bytes.c         every input byte 0x00-0xFF in every input field and flag parameter of
#                         every block acts as 0 or 1 and leaves a valid instance (all bytes
#                         natively, five under valgrind), and the clock going back;
#   tests/vectors.c       every vector file of `plc-timers vectors` through every form, every
#                         output compared, the RT column applied through the C API's reset
#                         (and a corrupted copy must fail);
#   examples/c/openplc_ton.c   prints what `plc-timers run TON --pt T#500ms` prints;
#   the README's C block  extracted, compiled as C99 and run by tests/readme_harness.c.
# Then install.sh installs into a temporary prefix, and a program is built against that copy
# through `pkg-config --cflags --libs plc_timers` and through CMake's find_package
# (tests/consumer/), and run.
#
# Needs a C and a C++ compiler, valgrind, pkg-config and cmake. valgrind and cmake come from
# Debian's packages: when one is missing and this runs as root with apt-get, the script
# installs it; otherwise it stops and says so.
set -euo pipefail
cd "$(dirname "$0")/../.."

target=${CARGO_TARGET_DIR:-target}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for tool in valgrind cmake pkg-config; do
    if ! command -v "$tool" >/dev/null; then
        if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
            echo "== bindings/c: installing $tool (apt-get)"
            apt-get update -qq && apt-get install -y -qq "$tool" >/dev/null
        else
            echo "bindings/c/ci.sh needs $tool: apt-get install $tool" >&2
            exit 1
        fi
    fi
done

echo "== bindings/c: the committed header is the fresh one (cbindgen)"
cargo test -q -p plc-timers-c --test header

echo "== bindings/c: Rust unit tests"
cargo test -q -p plc-timers-c --lib

echo "== bindings/c: libplc_timers.a and libplc_timers.so"
cargo build -q -p plc-timers-c --release
ls "$target/release/libplc_timers.a" "$target/release/libplc_timers.so"
# The soname build.rs gives (0.MINOR while the version is 0.x).
readelf -d "$target/release/libplc_timers.so" | grep -F 'Library soname: [libplc_timers.so.0.'
# The system libraries the static library needs, as rustc reports them for this platform.
native=$(cargo rustc -q -p plc-timers-c --release --crate-type staticlib -- \
    --print native-static-libs 2>&1 | sed -n 's/.*native-static-libs: //p' | tail -n 1)
echo "link line: $target/release/libplc_timers.a $native"

cflags=(-std=c11 -Wall -Wextra -Werror -O1 -g -Ibindings/c/include)
build() { # build OUT SOURCE: compile SOURCE and link it with the static library
    # shellcheck disable=SC2086 # $native is a list of -l flags
    cc "${cflags[@]}" "$2" "$target/release/libplc_timers.a" $native -o "$work/$1"
}
run() { valgrind -q --error-exitcode=1 --leak-check=full "$@"; }

echo "== bindings/c: the header compiles as C99, C11, C17, C++11 and C++17 (-pedantic)"
printf '#include "plc_timers.h"\nint main(void) { return PLC_TIMERS_OK; }\n' >"$work/h.c"
for std in c99 c11 c17; do
    cc -std=$std -Wall -Wextra -Werror -pedantic -Ibindings/c/include -fsyntax-only "$work/h.c"
done
for std in c++11 c++17; do
    c++ -x c++ -std=$std -Wall -Wextra -Werror -pedantic -Ibindings/c/include -fsyntax-only \
        "$work/h.c"
done

echo "== bindings/c: tests/layout.c (sizes, alignments, offsets)"
cc -std=c11 -Wall -Wextra -Werror -pedantic -Ibindings/c/include bindings/c/tests/layout.c \
    -o "$work/layout"
"$work/layout"

echo "== bindings/c: tests/status.c under valgrind"
build status bindings/c/tests/status.c
run "$work/status"

echo "== bindings/c: tests/vectors.c under valgrind, every vector file"
cargo run -q --release -- vectors "$work/vector-files"
build vectors bindings/c/tests/vectors.c
run "$work/vectors" "$work/vector-files"

echo "== bindings/c: tests/vectors.c finds a corrupted output"
cp -r "$work/vector-files" "$work/corrupted"
# The last row's last output (ET) of TON's example gets a 9 in front: 0 becomes 90.
sed -i '$ s/,\([0-9]*\)$/,9\1/' "$work/corrupted/TON/example.csv"
if "$work/vectors" "$work/corrupted" >/dev/null 2>"$work/corrupted.err"; then
    echo "tests/vectors.c passed a corrupted vector file" >&2
    exit 1
fi
grep -q 'TON/example.csv:.*column ET: expected 90, got 0' "$work/corrupted.err"
head -n 2 "$work/corrupted.err"

echo "== bindings/c: examples/c/openplc_ton.c under valgrind, as the CLI"
build openplc_ton examples/c/openplc_ton.c
run "$work/openplc_ton" >"$work/openplc_ton.csv"
cargo run -q --release -- run TON --pt T#500ms examples/traces/ton.csv | diff - "$work/openplc_ton.csv"
cat "$work/openplc_ton.csv"
echo "== bindings/c: tests/bytes.c: every input byte, natively; five bytes under valgrind"
build bytes bindings/c/tests/bytes.c
"$work/bytes"
run "$work/bytes" quick

echo "== bindings/c: the README's C block, run for 1 s of scans and on a fault, under valgrind"
# The README's only ```c block: a whole file defining the instance `ton` and `scan`.
awk '/^```c$/ {p = 1; next} /^```$/ {p = 0} p' README.md >"$work/readme.c"
test -s "$work/readme.c"
cc -std=c99 -Wall -Wextra -Werror -pedantic -O1 -g -Ibindings/c/include -c "$work/readme.c" \
    -o "$work/readme.o"
# shellcheck disable=SC2086 # $native is a list of -l flags
cc "${cflags[@]}" bindings/c/tests/readme_harness.c "$work/readme.o" \
    "$target/release/libplc_timers.a" $native -o "$work/readme"
run "$work/readme"

echo "== bindings/c: install.sh into a temporary prefix; pkg-config and CMake consumers"
prefix="$work/prefix"
bindings/c/install.sh "$prefix"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
pkg-config --cflags --libs plc_timers
pkg-config --modversion plc_timers
# shellcheck disable=SC2046 # pkg-config prints a list of flags
cc -std=c99 -Wall -Wextra -Werror -pedantic bindings/c/tests/consumer/consumer.c \
    $(pkg-config --cflags --libs plc_timers) -o "$work/consumer_pc"
readelf -d "$work/consumer_pc" | grep -F 'Shared library: [libplc_timers.so.0.'
LD_LIBRARY_PATH="$prefix/lib" "$work/consumer_pc"
cmake -S bindings/c/tests/consumer -B "$work/cmake" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_C_FLAGS="-Wall -Wextra -Werror" >/dev/null
cmake --build "$work/cmake" >/dev/null
LD_LIBRARY_PATH="$prefix/lib" "$work/cmake/consumer_shared"
"$work/cmake/consumer_static"
echo "bindings/c: all checks passed"
