#!/usr/bin/env bash
# Grading throughput, side by side: runs per minute of this build's `grade` (warm workers) against a
# baseline jar (one JVM per run), alternating, with the machine's load before and after each grading.
# The class of issue 31: 30 submissions (the bundled controllers that compile against both builds,
# three times each and Braitenberg and WallFollower a fourth time, the good test submissions alice,
# bob, carol and dave, and three careless ones: one that throws, one that hangs, one that spins in a
# thread pool) x 2 arenas x 5 seeds, 600 simulated seconds a run, --jobs 2, --wall-limit 30 for both
# builds (StepBraitenberg is left out: it uses parameters(), which the baseline's API lacks; the wall
# limit is lowered because the baseline keeps a run whose thread pool spins going until the limit,
# ten runs of 300 s at the default).
#
#   sim/src/test/bench/grade-bench.sh [ROUNDS]
#
# From the repository's root, after `mvn -q -DskipTests package`. Settings from the environment:
#   NEW=sim/target/khepera-sim.jar  BASE=/work/baseline/khepera-sim.jar  ROUNDS=2  SEEDS=5
#   SECONDS_PER_RUN=600  ARENAS="maze lab"  JOBS=2  WALL_LIMIT=30  NEW_ARGS=""  (e.g. NEW_ARGS="--worker-runs 1")
# It prints one line per grading and a summary; the reports stay in $WORK (a temporary folder).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../../../.." && pwd)
NEW=${NEW:-$ROOT/sim/target/khepera-sim.jar}
BASE=${BASE:-/work/baseline/khepera-sim.jar}
ROUNDS=${1:-${ROUNDS:-2}}
SEEDS=${SEEDS:-5}
SECONDS_PER_RUN=${SECONDS_PER_RUN:-600}
ARENAS=${ARENAS:-maze lab}
JOBS=${JOBS:-2}
WALL_LIMIT=${WALL_LIMIT:-30}
NEW_ARGS=${NEW_ARGS:-}
WORK=${WORK:-$(mktemp -d /tmp/grade-bench.XXXXXX)}
SUBS=$WORK/submissions

make_class() {
    rm -rf "$SUBS"
    mkdir -p "$SUBS"
    local src=$ROOT/controllers/src/main/java/org/kheperasim/controllers
    local n=0
    for c in Aggregation Braitenberg CapGatherer LightFollower MazeExplorer Template WallFollower \
        Aggregation Braitenberg CapGatherer LightFollower MazeExplorer Template WallFollower \
        Aggregation Braitenberg CapGatherer LightFollower MazeExplorer Template WallFollower Braitenberg WallFollower; do
        n=$((n + 1))
        local d=$SUBS/$(printf 'student%02d' $n)
        mkdir -p "$d"
        # In the default package, with the helper classes the bundled controllers share.
        for f in $c FailedSpots Odometry; do
            sed '/^package /d' "$src/$f.java" > "$d/$f.java"
        done
    done
    for s in alice bob carol dave frank grace; do
        cp -r "$ROOT/sim/src/test/resources/grade/$s" "$SUBS/$s"
    done
    mkdir -p "$SUBS/paula"
    cat > "$SUBS/paula/Pool.java" <<'EOF'
import org.kheperasim.api.*;

public class Pool extends Controller {
    private boolean started;

    @Override
    protected void doWork() {
        if (!started) {
            started = true;
            java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(2);
            for (int i = 0; i < 2; i++) {
                pool.submit(() -> {
                    long n = 0;
                    while (true) {
                        n++;
                    }
                });
            }
        }
        setSpeeds(3, 3);
        sleepMillis(100);
    }
}
EOF
}

load() {
    cut -d' ' -f1 /proc/loadavg
}

# grade LABEL JAR [ARGS...]: one grading; prints its line and records the runs per minute.
grade() {
    local label=$1 jar=$2
    shift 2
    local out=$WORK/out-$label-$round
    rm -rf "$out"
    local before
    before=$(load)
    local t0 t1
    t0=$(date +%s.%N)
    java -jar "$jar" grade --submissions "$SUBS" --arenas $ARENAS --seeds "$SEEDS" --seconds "$SECONDS_PER_RUN" \
        --jobs "$JOBS" --wall-limit "$WALL_LIMIT" --out "$out" "$@" > "$out.txt" 2> "$out.err" || { echo "$label failed: see $out.err"; exit 1; }
    t1=$(date +%s.%N)
    local runs wall rpm workers
    runs=$(($(wc -l < "$out/results.csv") - 1))
    wall=$(echo "$t1 - $t0" | bc -l)
    rpm=$(echo "$runs * 60 / $wall" | bc -l)
    workers=$(grep -o 'made [0-9]* runs on [0-9]* worker JVMs ([0-9]* replaced' "$out.err" | tail -1 || true)
    printf '%-8s round %d: %3d runs in %7.1f s = %6.1f runs/min; load %s -> %s; %s\n' "$label" "$round" "$runs" "$wall" \
        "$rpm" "$before" "$(load)" "${workers:-one JVM per run}"
    echo "$rpm" >> "$WORK/rpm-$label"
    tail -1 "$out/report.txt" | sed 's/^/           /'
}

make_class
echo "grade-bench: $(ls "$SUBS" | wc -l) submissions x ($ARENAS) x $SEEDS seeds, $SECONDS_PER_RUN s runs, --jobs $JOBS, --wall-limit $WALL_LIMIT; $(nproc) cores"
echo "new: $NEW $NEW_ARGS"
echo "baseline: $BASE"
rm -f "$WORK"/rpm-*
for round in $(seq 1 "$ROUNDS"); do
    grade baseline "$BASE"
    # shellcheck disable=SC2086
    grade new "$NEW" $NEW_ARGS
done
median() {
    sort -g "$1" | awk '{a[NR]=$1} END {m = NR % 2 ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2; printf "%.1f (min %.1f, max %.1f)", m, a[1], a[NR]}'
}
b=$(sort -g "$WORK/rpm-baseline" | awk '{s+=$1} END {print s/NR}')
n=$(sort -g "$WORK/rpm-new" | awk '{s+=$1} END {print s/NR}')
echo "runs/min, median: baseline $(median "$WORK/rpm-baseline"), new $(median "$WORK/rpm-new"); mean ratio new/baseline $(echo "$n / $b" | bc -l | cut -c1-4)"
echo "reports in $WORK"
