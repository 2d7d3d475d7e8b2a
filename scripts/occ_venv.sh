#!/usr/bin/env bash
# Prints the Python of a virtual environment with OpenCascade (the `cadquery-ocp` wheel),
# making it on first use: $RCAGD_OCC_VENV, default ~/.cache/rcagd/occ-venv.
#
#   py="$(scripts/occ_venv.sh)" && "$py" some_script.py
#   py="$(scripts/occ_venv.sh trimesh trimesh)"   # the same venv with another module
#
# Arguments: the module to import and the PyPI package that provides it (default `OCP`
# from `cadquery-ocp`). Exit status 3 when the environment cannot be made (no python3
# venv, PyPI unreachable).
set -euo pipefail

venv="${RCAGD_OCC_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/rcagd/occ-venv}"
python="${PYTHON:-python3}"

unavailable() {
    echo "occ: cannot set up OpenCascade: $*" >&2
    exit 3
}
if [[ ! -x "$venv/bin/python" ]]; then
    command -v "$python" >/dev/null 2>&1 || unavailable "no $python"
    echo "creating $venv ..." >&2
    mkdir -p "$(dirname "$venv")"
    "$python" -m venv "$venv" || { rm -rf "$venv"; unavailable "$python -m venv failed (python3-venv missing?)"; }
    "$venv/bin/pip" install --quiet --timeout 30 --retries 1 --upgrade pip >&2 || true
fi
module="${1:-OCP}"
package="${2:-cadquery-ocp}"
"$venv/bin/python" -c "import $module" 2>/dev/null || {
    echo "installing $package into $venv ..." >&2
    "$venv/bin/pip" install --quiet --timeout 30 --retries 2 "$package" >&2 ||
        unavailable "pip install $package failed (is PyPI reachable?)"
    "$venv/bin/python" -c "import $module" 2>/dev/null ||
        unavailable "$package installed but 'import $module' fails"
}
echo "$venv/bin/python"
