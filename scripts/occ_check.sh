#!/usr/bin/env bash
# Checks rcagd's STEP and IGES files in OpenCascade (see occ_check.py).
#
#   scripts/occ_check.sh DIR [occ_check.py options]
#
# DIR holds the files and their exact sidecars NAME.exact.json (rcagd_io::step::exact_sidecar).
# Without DIR, the exchange test writes its sample objects to a temporary directory
# (RCAGD_EXCHANGE_OUT) and those are checked.
#
# Makes a Python virtual environment ($RCAGD_OCC_VENV, default ~/.cache/rcagd/occ-venv)
# with the `cadquery-ocp` wheel from PyPI on first use.
#
# Exit status: 0 every file passes, 1 a file fails, 3 OpenCascade is unavailable
# (no python3 venv, PyPI unreachable).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
venv="${RCAGD_OCC_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/rcagd/occ-venv}"
python="${PYTHON:-python3}"

# Exit status 3 (not 1) when the environment cannot be made: no python3/venv, or
# PyPI unreachable. .ci/run skips the check then, and fails on 1.
unavailable() {
    echo "occ_check: cannot set up OpenCascade: $*" >&2
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

if [[ $# -ge 1 && "$1" != -* ]]; then
    dir="$1"
    shift
else
    dir="$(mktemp -d)"
    echo "writing the exchange test's sample files to $dir ..." >&2
    (cd "$root" && RCAGD_EXCHANGE_OUT="$dir" cargo test --quiet -p rcagd-io --test it exchange::write_gallery_files >&2)
fi

exec "$venv/bin/python" "$here/occ_check.py" "$dir" "$@"
