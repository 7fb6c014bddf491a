#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# tools/lint.sh format          check that every C++ file follows .clang-format
# tools/lint.sh fix             reformat every C++ file with .clang-format
# tools/lint.sh tidy BUILD_DIR  run .clang-tidy over every C++ source, with BUILD_DIR's
#                               compile_commands.json, two files at a time, skipping those whose
#                               exact input passed before (tools/tidy.py)
set -eu
cd "$(dirname "$0")/.."
# The fuzz targets are formatted too, but built only in the fuzz preset: tidy, which needs their
# compile commands, leaves them out.
all_sources() {
    find core widgets app resources translations tests benchmarks fuzz -name '*.cpp' "$@" | sort
}
case "${1:-}" in
format)
    all_sources -o -name '*.h' | xargs clang-format --dry-run -Werror
    echo "format: all files follow .clang-format"
    ;;
fix)
    all_sources -o -name '*.h' | xargs clang-format -i
    echo "fix: every file reformatted"
    ;;
tidy)
    build_dir=${2:?usage: tools/lint.sh tidy BUILD_DIR}
    # Compiler warnings are the compiler's business (CI builds with -Werror); only the
    # clang-tidy checks are judged here. A file whose exact input passed before is not checked
    # again (tools/tidy.py, tools/tidy-passed.txt).
    exec python3 tools/tidy.py "$build_dir"
    ;;
*)
    echo "usage: tools/lint.sh format | fix | tidy BUILD_DIR" >&2
    exit 2
    ;;
esac
