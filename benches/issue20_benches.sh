#!/usr/bin/env bash
# Issue 20's "before/after ratios from one run for every exact benchmark"
# (docs/BENCHMARKS.md, "Issue 20: every benchmark before/after"): runs every criterion
# benchmark id that exists in both versions' bench binaries, the two versions alternately,
# ROUNDS rounds, and prints one row per id and round with criterion's point estimates (the
# middle value of `time: [low estimate high]`, converted to microseconds).
#
#   bash benches/issue20_benches.sh BEFORE_DEPS AFTER_DEPS [ROUNDS] [MEASURE_S] > rows.txt
#
# BEFORE_DEPS / AFTER_DEPS: the `target/release/deps` folders after `cargo bench --no-run`
# of each version (the bench binaries are found there by name: canal_degree, export,
# grid_eval, ph, ph_planar, pipe_compare, pn_offset, sphere_map — the benches that existed
# when the issue was filed; a binary's newest build is taken).
set -euo pipefail
before_deps="$1"
after_deps="$2"
rounds="${3:-2}"
measure="${4:-2}"
benches=(canal_degree export grid_eval ph ph_planar pipe_compare pn_offset sphere_map)

newest_bin() {
    # the newest executable deps/NAME-HASH (no extension: not a .d file)
    find "$1" -maxdepth 1 -type f -executable -name "$2-*" ! -name '*.*' -printf '%T@ %p\n' |
        sort -n | tail -1 | cut -d' ' -f2-
}

to_us() {
    # "12.3 ms" -> microseconds
    awk -v v="$1" -v u="$2" 'BEGIN {
        f = 1; if (u == "ns") f = 0.001; else if (u == "ms") f = 1000; else if (u == "s") f = 1e6;
        printf "%.3f", v * f }'
}

run_one() {
    # run_one BIN ID -> the point estimate in microseconds, or "-" if the run failed
    # a fresh criterion folder per run: no saved baseline, so no "change: time: [...]" line
    local out home
    home="$(mktemp -d)"
    out="$(CRITERION_HOME="$home" "$1" --bench --exact "$2" --warm-up-time 0.5 \
        --measurement-time "$measure" --noplot 2>/dev/null)" || { rm -rf "$home"; echo "-"; return; }
    rm -rf "$home"
    local est unit
    # the first "time:   [1.2345 ms 1.2400 ms 1.2500 ms]": the middle value and its unit
    read -r est unit < <(echo "$out" | grep -m1 -o 'time: *\[[^]]*\]' | tr -d '[]' | awk '{ print $4, $5 }')
    if [ -z "${est:-}" ]; then echo "-"; return; fi
    [ "$unit" = "µs" ] && unit=us
    to_us "$est" "$unit"
}

echo "# bench id round before_us after_us after/before"
for b in "${benches[@]}"; do
    bb="$(newest_bin "$before_deps" "$b")"
    ab="$(newest_bin "$after_deps" "$b")"
    if [ -z "$bb" ] || [ -z "$ab" ]; then
        echo "# $b: missing binary (before: ${bb:-none}, after: ${ab:-none})"
        continue
    fi
    comm -12 <("$bb" --bench --list 2>/dev/null | sed -n 's/: benchmark$//p' | sort -u) \
             <("$ab" --bench --list 2>/dev/null | sed -n 's/: benchmark$//p' | sort -u) > /tmp/issue20-ids.$$
    while IFS= read -r id; do
        for round in $(seq 1 "$rounds"); do
            x="$(run_one "$bb" "$id")"
            y="$(run_one "$ab" "$id")"
            r="-"
            if [ "$x" != "-" ] && [ "$y" != "-" ]; then
                r="$(awk -v a="$x" -v b="$y" 'BEGIN { if (a > 0) printf "%.3f", b / a; else print "-" }')"
            fi
            printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$b" "$id" "$round" "$x" "$y" "$r"
        done
    done < /tmp/issue20-ids.$$
    rm -f /tmp/issue20-ids.$$
done
