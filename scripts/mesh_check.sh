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
py="$("$here/occ_venv.sh" trimesh trimesh)" || exit 3
exec "$py" "$here/mesh_check.py" "$@"
