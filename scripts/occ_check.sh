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
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
venv="${RCAGD_OCC_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/rcagd/occ-venv}"
python="${PYTHON:-python3}"

if [[ ! -x "$venv/bin/python" ]]; then
    echo "creating $venv with cadquery-ocp (OpenCascade) from PyPI ..." >&2
    mkdir -p "$(dirname "$venv")"
    "$python" -m venv "$venv"
    "$venv/bin/pip" install --quiet --upgrade pip
    "$venv/bin/pip" install --quiet cadquery-ocp
fi
"$venv/bin/python" -c "import OCP" 2>/dev/null || {
    echo "installing cadquery-ocp into $venv ..." >&2
    "$venv/bin/pip" install --quiet cadquery-ocp
}

if [[ $# -ge 1 && "$1" != -* ]]; then
    dir="$1"
    shift
else
    dir="$(mktemp -d)"
    echo "writing the exchange test's sample files to $dir ..." >&2
    (cd "$root" && RCAGD_EXCHANGE_OUT="$dir" cargo test --quiet -p rcagd-io --test exchange write_gallery_files >&2)
fi

exec "$venv/bin/python" "$here/occ_check.py" "$dir" "$@"
