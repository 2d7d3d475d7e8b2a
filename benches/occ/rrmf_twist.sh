#!/usr/bin/env bash
# The twist comparison of docs/BENCHMARKS.md in one run: rcagd's exact twist-free sweep of
# an ellipse along an RRMF quintic (benches/occ/rrmf_twist.toml) and OpenCascade's sweeps
# of the same ellipse along the same spine (benches/occ/rrmf_twist.py).
#
#   bash benches/occ/rrmf_twist.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
py="$(scripts/occ_venv.sh)"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "== rcagd: exact RMF sweep (build + certificates, release)"
cargo build --quiet --release -p rcagd-cli
/usr/bin/time -f "rcagd build: %e s wall, %U s user" \
    target/release/rcagd build benches/occ/rrmf_twist.toml --out "$out" --format json,step
echo "== OpenCascade sweeps, and rcagd's STEP read by OpenCascade"
"$py" benches/occ/rrmf_twist.py "$out"
