#!/usr/bin/env bash
# Checks rcagd's triangle meshes with trimesh (see mesh_check.py).
#
#   scripts/mesh_check.sh DIR [mesh_check.py options, e.g. --all-closed]
#
# Uses the virtual environment of occ_check.sh ($RCAGD_OCC_VENV, default
# ~/.cache/rcagd/occ-venv), making it if needed, and installs trimesh (with numpy) from
# PyPI into it on first use.
#
# Exit status: 0 every file passes, 1 a file fails, 3 trimesh is unavailable (no python3
# venv, PyPI unreachable).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
venv="${RCAGD_OCC_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/rcagd/occ-venv}"
python="${PYTHON:-python3}"

unavailable() {
    echo "mesh_check: cannot set up trimesh: $*" >&2
    exit 3
}
if [[ ! -x "$venv/bin/python" ]]; then
    command -v "$python" >/dev/null 2>&1 || unavailable "no $python"
    mkdir -p "$(dirname "$venv")"
    "$python" -m venv "$venv" || { rm -rf "$venv"; unavailable "$python -m venv failed"; }
fi
"$venv/bin/python" -c "import trimesh" 2>/dev/null || {
    echo "installing trimesh into $venv ..." >&2
    "$venv/bin/pip" install --quiet --timeout 30 --retries 2 trimesh >&2 ||
        unavailable "pip install trimesh failed (is PyPI reachable?)"
}
exec "$venv/bin/python" "$here/mesh_check.py" "$@"
