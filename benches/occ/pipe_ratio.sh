#!/usr/bin/env bash
# The exact pipe against OpenCascade's BRepOffsetAPI_MakePipe with a stable ratio: both sides
# timed alternately in one run, many builds each, median and spread of both
# (benches/occ/pipe_ratio.py; docs/BENCHMARKS.md, "Pipes against OpenCascade").
#
#   bash benches/occ/pipe_ratio.sh [ROUNDS [BUILDS_PER_ROUND [LABEL=PIPE_PROFILE_BINARY...]]]
#
# Defaults: 10 rounds of 20 builds per side and spine, the release `pipe_profile` of this
# tree (built here: `cargo bench -p rcagd-benches --bench pipe_profile --no-run`). Pass
# several LABEL=BINARY to time two versions of rcagd in the same run (e.g. before=… after=…).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
rounds="${1:-10}"
n="${2:-20}"
shift $(( $# > 2 ? 2 : $# ))
py="$(scripts/occ_venv.sh)"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
if [ $# -eq 0 ]; then
    bin="$(cargo bench --quiet -p rcagd-benches --bench pipe_profile --no-run --message-format=json \
        | "$py" -c 'import json,sys
for l in sys.stdin:
    m = json.loads(l)
    if m.get("reason") == "compiler-artifact" and m.get("executable") and m["target"]["name"] == "pipe_profile":
        print(m["executable"])')"
    set -- "this=$bin"
fi
# the spines as STEP curves, written by rcagd (any build of the CLI: the curve is exact)
cli="${RCAGD_CLI:-}"
if [ -z "$cli" ]; then
    cargo build --quiet -p rcagd-cli
    cli=target/debug/rcagd
fi
cat > "$out/spines.toml" <<'TOML'
[[object]]
name = "gallery"
op = "ph_curve"
quaternions = [[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]]

[[object]]
name = "issue"
op = "ph_curve"
quaternions = [[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]]
TOML
"$cli" build "$out/spines.toml" --out "$out" --format step >/dev/null
echo "command: bash benches/occ/pipe_ratio.sh $rounds $n $*"
"$py" benches/occ/pipe_ratio.py "$out" "$rounds" "$n" "$@"
