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
# Exit status 3 (not 1) when the environment cannot be made: no python3/venv, or
# PyPI unreachable. .ci/run skips the check then, and fails on 1.
py="$("$here/occ_venv.sh")" || exit 3

if [[ $# -ge 1 && "$1" != -* ]]; then
    dir="$1"
    shift
else
    dir="$(mktemp -d)"
    echo "writing the exchange test's sample files to $dir ..." >&2
    (cd "$root" && RCAGD_EXCHANGE_OUT="$dir" cargo test --quiet -p rcagd-io --test it exchange::write_gallery_files >&2)
fi

exec "$py" "$here/occ_check.py" "$dir" "$@"
