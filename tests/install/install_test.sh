#!/usr/bin/env bash
# `cmake --install` into a scratch prefix, then scene A three ways from the installation alone:
# the installed isosid-run, a separate CMake project that finds the library with
# find_package(isosid) and runs the scene in-process, and the installed Python package (imported
# outside the source tree). All three must give the same peak force to the last digit.
#   install_test.sh BUILD_DIR SOURCE_DIR PYTHON
set -euo pipefail
build=$1 src=$2 python=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
cp "$src/models/sphere_hertz.scene.toml" "$src/models/sphere_axisym.model.toml" "$work/"
cd "$work"
unset ISOSID_BUILD_DIR
ISOSID_PREP="$work/prefix/bin/isosid-prep" prefix/bin/isosid-run -q sphere_hertz.scene.toml -o cli
cli=$("$python" -c 'import json; print(repr(json.load(open("cli/summary.json"))["contacts"][0]["peak_force_n"]))')
library=$(ISOSID_PREP="$work/prefix/bin/isosid-prep" consumer/run_scene sphere_hertz.scene.toml library)
site=$(find "$work/prefix/lib" -type d -path '*dist-packages/isosid' | head -1)
# no ISOSID_PREP: the installed package finds the installed isosid-prep itself
from_python=$(env -u ISOSID_PREP PYTHONPATH="$(dirname "$site")" "$python" -c \
  "import isosid; print(isosid.__file__.startswith('$work'), repr(isosid.run('sphere_hertz.scene.toml', output='py', progress=False).contacts['impact'].peak_force_n))")
echo "isosid-run $cli, find_package(isosid) $library, Python $from_python"
[ "$from_python" = "True $cli" ] || { echo "the installed Python package differs (or was not the one imported)"; exit 1; }
"$python" -c "import sys; sys.exit(0 if float('$library') == float('$cli') else 1)" || { echo "the library's peak differs"; exit 1; }
