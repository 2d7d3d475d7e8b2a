#!/usr/bin/env bash
# The pipe comparisons against OpenCascade of docs/BENCHMARKS.md in one run: the gallery's
# PH quintic spine (exact pipe) and the OpenCascade-written cubic B-spline of
# examples/spines/bspline_spine.step (exact pipe around a certified PH spline), each against
# OpenCascade's BRepOffsetAPI_MakePipe of the same radius along the same spine
# (benches/occ/bspline_pipe.py measures both surfaces through the same code).
#
#   bash benches/occ/pipe_compare.sh
#
# Its times are single measurements (OpenCascade: median of 7 builds that each read the
# spine's STEP file; rcagd: the CPU time of the whole CLI process): for a ratio that is
# stable under load use benches/occ/pipe_ratio.sh (both sides alternately, many builds,
# OpenCascade with and without the file read).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
py="$(scripts/occ_venv.sh)"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
cargo build --quiet --release -p rcagd-cli
cat > "$out/ph.toml" <<'TOML'
[[object]]
name = "ph_spine"
op = "ph_curve"
quaternions = [[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]]

[[object]]
name = "ph_pipe"
op = "pipe_ph"
coefficients = [[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]]
radius = "1/10"
TOML
cat > "$out/bspline.toml" <<TOML
[[object]]
name = "bspline_pipe"
op = "pipe"
spine_file = "$root/examples/spines/bspline_spine.step"
radius = "1/5"
TOML
cpu() { /usr/bin/time -f %U "$@" 2>&1 >/dev/null | tail -1; }
echo "== PH quintic spine (gallery pipe_ph_quintic), radius 1/10"
t="$(cpu ./target/release/rcagd build "$out/ph.toml" --out "$out" --format step)"
"$py" benches/occ/bspline_pipe.py bench 0.1 "$out/ph_spine.step" "$out/ph_pipe.step" "$t" | grep '|'
echo "== cubic B-spline spine (examples/spines/bspline_spine.step), radius 1/5"
t="$(cpu ./target/release/rcagd build "$out/bspline.toml" --out "$out" --format step)"
"$py" benches/occ/bspline_pipe.py bench 0.2 examples/spines/bspline_spine.step "$out/bspline_pipe.step" "$t" | grep '|'
