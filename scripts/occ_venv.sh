#!/usr/bin/env bash
# Prints the Python of a virtual environment with OpenCascade (the `cadquery-ocp` wheel),
# making it on first use: $RCAGD_OCC_VENV, default ~/.cache/rcagd/occ-venv.
#
#   py="$(scripts/occ_venv.sh)" && "$py" some_script.py
#
# Exit status 3 when the environment cannot be made (no python3 venv, PyPI unreachable).
set -euo pipefail

venv="${RCAGD_OCC_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/rcagd/occ-venv}"
python="${PYTHON:-python3}"

unavailable() {
    echo "occ: cannot set up OpenCascade: $*" >&2
    exit 3
}
if [[ ! -x "$venv/bin/python" ]]; then
    command -v "$python" >/dev/null 2>&1 || unavailable "no $python"
    echo "creating $venv with cadquery-ocp (OpenCascade) from PyPI ..." >&2
    mkdir -p "$(dirname "$venv")"
    "$python" -m venv "$venv" || { rm -rf "$venv"; unavailable "$python -m venv failed (python3-venv missing?)"; }
    "$venv/bin/pip" install --quiet --timeout 30 --retries 1 --upgrade pip >&2 || true
fi
"$venv/bin/python" -c "import OCP" 2>/dev/null || {
    echo "installing cadquery-ocp into $venv ..." >&2
    "$venv/bin/pip" install --quiet --timeout 30 --retries 2 cadquery-ocp >&2 ||
        unavailable "pip install cadquery-ocp failed (is PyPI reachable?)"
    "$venv/bin/python" -c "import OCP" 2>/dev/null ||
        unavailable "cadquery-ocp installed but 'import OCP' fails"
}
echo "$venv/bin/python"
