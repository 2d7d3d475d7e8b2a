#!/usr/bin/env bash
# The cyclide-blend comparison of docs/BENCHMARKS.md in one run: rcagd's exact blends
# (criterion bench benches/cyclide_blend.rs), their STEP files, and OpenCascade's blends of
# the same cylinders measured against the exact surfaces (benches/occ/cyclide_blend.py).
#
#   bash benches/occ/cyclide_blend.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
py="$(scripts/occ_venv.sh)"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "== rcagd: exact blends (criterion)"
cargo bench -p rcagd-benches --features bench --bench cyclide_blend -- \
    --warm-up-time 1 --measurement-time 3 2>&1 | grep -E '^cyclide_blend|time:'
echo "== rcagd: STEP files of examples/recipes/cyclide.toml"
cargo run --quiet -p rcagd-cli -- build examples/recipes/cyclide.toml --out "$out" --format step
echo "== OpenCascade, and rcagd's STEP read by OpenCascade"
"$py" benches/occ/cyclide_blend.py "$out"
