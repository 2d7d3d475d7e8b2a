#!/usr/bin/env bash
# Issue 20's before/after of the gallery (docs/BENCHMARKS.md, "Issue 20: before/after"): two
# release CLIs build every recipe of RECIPE_DIR alternately, two rounds; prints per recipe
# and version the exit status, user and system CPU seconds and the wall time, then the
# total CPU (user + system) per round and version.
#
#   bash benches/issue20_before_after.sh BEFORE/target/release/rcagd target/release/rcagd BEFORE/examples/recipes
set -euo pipefail
before="$1"
after="$2"
dir="$3"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "round recipe version status user_s system_s wall_s"
for round in 1 2; do
    for recipe in "$dir"/*.toml; do
        r="$(basename "$recipe" .toml)"
        for v in before after; do
            bin="$before"
            [ "$v" = after ] && bin="$after"
            rc=0
            /usr/bin/time -o "$out/time" -f "%U %S %e" "$bin" build "$recipe" >"$out/json" 2>"$out/err" || rc=$?
            echo "$round $r $v $rc $(tail -1 "$out/time")" | tee -a "$out/rows"
        done
    done
done
awk '{ cpu[$1 " " $3] += $5 + $6 } END { for (k in cpu) printf "total round %s CPU %.2f s\n", k, cpu[k] }' "$out/rows" | sort
