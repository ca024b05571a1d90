#!/usr/bin/env bash
# This engine against Enki by CPU time, side by side: for each swarm size, alternate one Enki process
# (../shared/enki-bench's enki_bench, physics every 100 ms) and one `khepera-sim bench` process over the
# same simulated time per run (N robots, one per 200 mm cell in a walled square, the on-board
# StepBraitenberg), ROUNDS times. Enki's CPU is its whole process's (user + sys, from the OS's
# accounting; its start-up is about 0.002 s); this engine's is the process CPU of its measured runs,
# the JIT's and collector's threads included, after `bench`'s warm-up (the JVM's start-up is measured
# apart: docs/startup.md), the median of RUNS runs. Per round: both, the load and the peak RSS; per size:
# the medians over rounds with min-max, and the speed ratio this / Enki by CPU (above 1: this is faster).
#
#   sim/src/test/bench/enki-pairs.sh [ROUNDS]
#
# From the repository's root, after `mvn -q -DskipTests package`. Settings from the environment:
#   JAR=sim/target/khepera-sim.jar  ENKI=/work/enki/enki_bench  ROUNDS=5  RUNS=3
#   SIZES="1:6000 10:1200 100:300 1000:60"  (robots:simulated seconds per run)  JAVA_OPTS=""
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../../../.." && pwd)
JAR=${JAR:-$ROOT/sim/target/khepera-sim.jar}
ENKI=${ENKI:-/work/enki/enki_bench}
ROUNDS=${1:-${ROUNDS:-5}}
RUNS=${RUNS:-3}
SIZES=${SIZES:-1:6000 10:1200 100:300 1000:60}
JAVA_OPTS=${JAVA_OPTS:-}
OUT=$(mktemp -d /tmp/enki-pairs.XXXXXX)

median() { # median COLUMN FILE: "median (min-max)"
    sort -g -k"$1","$1" "$2" | awk -v c="$1" '{v[NR]=$c} END {m = NR % 2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2;
        printf "%.1f (%.1f-%.1f)", m, v[1], v[NR]}'
}

for size in $SIZES; do
    n=${size%%:*}
    s=${size##*:}
    for r in $(seq 1 "$ROUNDS"); do
        load=$(cut -d' ' -f1 /proc/loadavg)
        /usr/bin/time -f '%U %S %e %M' -o "$OUT/e.t" "$ENKI" "$n" "$s" 1 "$r" > "$OUT/e.log" 2>&1
        awk -v n="$n" -v s="$s" '{printf "%.2f %.2f %d\n", ($1 + $2) * 1e6 / (n * s), $3 * 1e6 / (n * s), $4}' \
            "$OUT/e.t" >> "$OUT/enki-$n"
        # shellcheck disable=SC2086
        /usr/bin/time -f '%M' -o "$OUT/t.t" java $JAVA_OPTS -jar "$JAR" bench --robots "$n" \
            --controller StepBraitenberg --seconds "$s" --runs "$RUNS" --seed "$r" > "$OUT/t.log" 2>&1
        cpu=$(sed -n 's/^median CPU: \([0-9.]*\) us.*/\1/p' "$OUT/t.log")
        wall=$(awk -v n="$n" '/^median: /{gsub(",", "", $2); printf "%.2f", 1e6 / ($2 * n)}' "$OUT/t.log")
        echo "$cpu $wall $(cat "$OUT/t.t")" >> "$OUT/this-$n"
        echo "N=$n round $r (load $load): us per robot-second by CPU, wall; peak RSS KB:" \
            "enki $(tail -1 "$OUT/enki-$n")  this $(tail -1 "$OUT/this-$n")"
    done
    ec=$(median 1 "$OUT/enki-$n" | cut -d' ' -f1)
    tc=$(median 1 "$OUT/this-$n" | cut -d' ' -f1)
    ew=$(median 2 "$OUT/enki-$n" | cut -d' ' -f1)
    tw=$(median 2 "$OUT/this-$n" | cut -d' ' -f1)
    echo "N=$n, $s s a run: us per robot-second by CPU enki $(median 1 "$OUT/enki-$n"), this" \
        "$(median 1 "$OUT/this-$n"); by wall enki $(median 2 "$OUT/enki-$n"), this $(median 2 "$OUT/this-$n");" \
        "peak RSS KB enki $(median 3 "$OUT/enki-$n"), this $(median 3 "$OUT/this-$n")"
    awk -v n="$n" -v ec="$ec" -v tc="$tc" -v ew="$ew" -v tw="$tw" 'BEGIN {
        printf "N=%s: speed this / enki by CPU %.2f (by wall %.2f)\n", n, ec / tc, ew / tw }'
done
echo "(the last processes' outputs in $OUT)"
