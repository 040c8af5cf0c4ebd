#!/usr/bin/env bash
# Installs the C library under PREFIX in the layout of cargo-c's `cargo cinstall` (the Rust
# ecosystem's tool for C libraries, whose Debian build, 0.9.14, cannot read this workspace's
# version-4 Cargo.lock), plus a CMake package:
#   PREFIX/include/plc_timers.h
#   PREFIX/lib/libplc_timers.a
#   PREFIX/lib/libplc_timers.so.X.Y.Z, libplc_timers.so.SOVER -> it, libplc_timers.so -> that
#   PREFIX/lib/pkgconfig/plc_timers.pc
#   PREFIX/lib/cmake/plc_timers/plc_timers-config.cmake, plc_timers-config-version.cmake
# SOVER is 0.MINOR while the version is 0.x (a minor release may change the ABI), else MAJOR:
# the soname build.rs gives the library. The CMake files find the prefix from their own place,
# so the tree can be moved; the .pc file names PREFIX (pkg-config's usual way).
#
# Usage: bindings/c/install.sh PREFIX   (DESTDIR is honoured, as by `make install`)
set -euo pipefail
cd "$(dirname "$0")/../.."
prefix=${1:?usage: bindings/c/install.sh PREFIX}
case $prefix in /*) ;; *) prefix="$PWD/$prefix" ;; esac
dest="${DESTDIR:-}$prefix"
target=${CARGO_TARGET_DIR:-target}

version=$(sed -n 's/^version = "\(.*\)"$/\1/p' bindings/c/Cargo.toml | head -n 1)
major=${version%%.*}
rest=${version#*.}
minor=${rest%%.*}
if [ "$major" = 0 ]; then sover="0.$minor"; else sover="$major"; fi

cargo build -q -p plc-timers-c --release
native=$(cargo rustc -q -p plc-timers-c --release --crate-type staticlib -- \
    --print native-static-libs 2>&1 | sed -n 's/.*native-static-libs: //p' | tail -n 1)

install -d "$dest/include" "$dest/lib/pkgconfig" "$dest/lib/cmake/plc_timers"
install -m 644 bindings/c/include/plc_timers.h "$dest/include/"
install -m 644 "$target/release/libplc_timers.a" "$dest/lib/"
install -m 755 "$target/release/libplc_timers.so" "$dest/lib/libplc_timers.so.$version"
ln -sf "libplc_timers.so.$version" "$dest/lib/libplc_timers.so.$sover"
ln -sf "libplc_timers.so.$sover" "$dest/lib/libplc_timers.so"

cat >"$dest/lib/pkgconfig/plc_timers.pc" <<PC
prefix=$prefix
exec_prefix=\${prefix}
libdir=\${exec_prefix}/lib
includedir=\${prefix}/include

Name: plc_timers
Description: Siemens S7 PLC timers and counters (S5, IEC) behind a C ABI
Version: $version
Libs: -L\${libdir} -lplc_timers
Libs.private: $native
Cflags: -I\${includedir}
PC

# The native libraries as CMake's list (the -l prefixes dropped).
cmake_native=$(printf '%s\n' $native | sed -n 's/^-l//p' | paste -sd ';' -)
cat >"$dest/lib/cmake/plc_timers/plc_timers-config.cmake" <<CMAKE
# plc_timers $version: the imported targets plc_timers::plc_timers (shared library) and
# plc_timers::static (static library with the system libraries it needs).
get_filename_component(_plc_timers_prefix "\${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET plc_timers::plc_timers)
  add_library(plc_timers::plc_timers SHARED IMPORTED)
  set_target_properties(plc_timers::plc_timers PROPERTIES
    IMPORTED_LOCATION "\${_plc_timers_prefix}/lib/libplc_timers.so.$version"
    IMPORTED_SONAME "libplc_timers.so.$sover"
    INTERFACE_INCLUDE_DIRECTORIES "\${_plc_timers_prefix}/include")
  add_library(plc_timers::static STATIC IMPORTED)
  set_target_properties(plc_timers::static PROPERTIES
    IMPORTED_LOCATION "\${_plc_timers_prefix}/lib/libplc_timers.a"
    INTERFACE_INCLUDE_DIRECTORIES "\${_plc_timers_prefix}/include"
    INTERFACE_LINK_LIBRARIES "$cmake_native")
endif()
unset(_plc_timers_prefix)
CMAKE

cat >"$dest/lib/cmake/plc_timers/plc_timers-config-version.cmake" <<CMAKE
# Compatible when the requested version is not newer and has the same ABI series (the soname's
# $sover): the same 0.minor while the version is 0.x, the same major after.
set(PACKAGE_VERSION "$version")
set(PACKAGE_VERSION_COMPATIBLE FALSE)
if(NOT PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION
   AND PACKAGE_FIND_VERSION_MAJOR EQUAL $major
   AND ($major GREATER 0 OR PACKAGE_FIND_VERSION_MINOR EQUAL $minor))
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
  if(PACKAGE_FIND_VERSION VERSION_EQUAL PACKAGE_VERSION)
    set(PACKAGE_VERSION_EXACT TRUE)
  endif()
endif()
CMAKE
echo "installed plc_timers $version (soname libplc_timers.so.$sover) under $dest"
