#!/usr/bin/env bash
# Installs the built penumbra into a temporary prefix, builds the consumer project
# against it with find_package(penumbra), and runs it on a fixture scene.
set -euo pipefail
build_dir=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
test -x "$work/prefix/bin/penumbra"
test -f "$work/prefix/lib/cmake/penumbra/penumbraConfig.cmake" || test -f "$work/prefix/lib64/cmake/penumbra/penumbraConfig.cmake"
cmake -S "$source_dir/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/consumer" > "$work/build.log"
count=$("$work/consumer/consumer" "$source_dir/fixtures/scenes/every-kind.json")
[ "$count" = 7 ] || { echo "consumer counted $count objects, expected 7"; exit 1; }
echo "installed package found and used: 7 objects"
