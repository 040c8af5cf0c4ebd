#!/usr/bin/env bash
# The C ABI's checks (issue 27), run by .ci/run: the committed header is the one cbindgen
# generates now; the static and shared libraries build; the C tests and the example, compiled
# by the system's C compiler with -Wall -Wextra -Werror and linked with the static library, pass
# under valgrind (memcheck, --error-exitcode=1):
#   tests/status.c        every status code, the IEC timers' structure operations, the memory
#                         areas' STL operations;
#   tests/vectors.c       every vector file of `plc-timers vectors` through every form, every
#                         output compared, the RT column applied through the C API's reset
#                         (and a corrupted copy must fail);
#   examples/c/openplc_ton.c   prints what `plc-timers run TON --pt T#500ms` prints.
#
# Needs a C compiler (`cc`) and valgrind. valgrind comes from Debian's packages: when it is
# missing and this runs as root with apt-get, the script installs it (`apt-get install
# valgrind`); otherwise it stops and says so.
set -euo pipefail
cd "$(dirname "$0")/../.."

target=${CARGO_TARGET_DIR:-target}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if ! command -v valgrind >/dev/null; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
        echo "== bindings/c: installing valgrind (apt-get)"
        apt-get update -qq && apt-get install -y -qq valgrind >/dev/null
    else
        echo "bindings/c/ci.sh needs valgrind: apt-get install valgrind" >&2
        exit 1
    fi
fi

echo "== bindings/c: the committed header is the fresh one (cbindgen)"
cargo test -q -p plc-timers-c --test header

echo "== bindings/c: Rust unit tests"
cargo test -q -p plc-timers-c --lib

echo "== bindings/c: libplc_timers.a and libplc_timers.so"
cargo build -q -p plc-timers-c --release
ls "$target/release/libplc_timers.a" "$target/release/libplc_timers.so"
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

echo "== bindings/c: the header compiles as C99 and as C++"
printf '#include "plc_timers.h"\nint main(void) { return PLC_TIMERS_OK; }\n' >"$work/h.c"
cc -std=c99 -Wall -Wextra -Werror -pedantic -Ibindings/c/include -fsyntax-only "$work/h.c"
if command -v c++ >/dev/null; then
    c++ -x c++ -Wall -Wextra -Werror -Ibindings/c/include -fsyntax-only "$work/h.c"
else
    echo "(no C++ compiler: the C++ check is skipped)"
fi

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
echo "== bindings/c: the README's C example compiles against the header"
# The block after the README's link line: its first line is the #include; the rest is scan
# code, wrapped here in a function that declares the runtime's names it uses.
awk '/^```c$/ {p = 1; next} /^```$/ {p = 0} p' README.md >"$work/readme.c.in"
{
    head -n 1 "$work/readme.c.in"
    echo 'bool readme_example(bool button, uint64_t now_ms) {'
    echo '    bool lamp = false;'
    tail -n +2 "$work/readme.c.in"
    echo '    return lamp;'
    echo '}'
} >"$work/readme.c"
cc -std=c11 -Wall -Wextra -Werror -Ibindings/c/include -c "$work/readme.c" -o "$work/readme.o"
echo "bindings/c: all checks passed"
