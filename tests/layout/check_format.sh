#!/usr/bin/env bash
# Checks that every C++ source of the project is formatted as .clang-format says
# (clang-format --dry-run -Werror): prints the files that are not, exits 1 if any.
set -euo pipefail
cd "$1"
mapfile -t files < <(git ls-files -- '*.h' '*.cpp' 2>/dev/null ||
                     find include src tests bench -name '*.h' -o -name '*.cpp')
clang-format --dry-run -Werror "${files[@]}"
echo "${#files[@]} files formatted"
