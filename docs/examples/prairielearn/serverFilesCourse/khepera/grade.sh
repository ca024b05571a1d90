#!/usr/bin/env bash
# PrairieLearn's external grader entrypoint: grades the student's files in /grade/student with
# khepera-sim grade over the arenas and seeds of the question's tests/grade.conf and writes
# /grade/results/results.json. GRADE_ROOT names another root with the same layout (to try it locally).
set -u
ROOT="${GRADE_ROOT:-/grade}"
# shellcheck source=/dev/null
. "$ROOT/tests/grade.conf"
KSIM_CLASSPATH="${KSIM_CLASSPATH:-$ROOT/serverFilesCourse/khepera/khepera-sim.jar}"
JAVA="${JAVA:-java}"
mkdir -p "$ROOT/results"
RESULTS="$ROOT/results/results.json"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/hand-ins/submission"
cp -R "$ROOT/student/." "$work/hand-ins/submission/"
args=(grade --submissions "$work/hand-ins" --arenas $ARENAS --seeds "$SEEDS" --jobs 1 --heap-mb "$HEAP_MB"
      --deadline "$DEADLINE" --format prairielearn --out "$work/report" --no-sandbox)
if [ -n "${HIDDEN:-}" ]; then args+=(--hidden $HIDDEN); fi
if [ -n "${SECONDS_PER_RUN:-}" ]; then args+=(--seconds "$SECONDS_PER_RUN"); fi
(cd "$ROOT/tests" && "$JAVA" -Xmx"${GRADER_HEAP_MB}"m -XX:+UseSerialGC -XX:ActiveProcessorCount=1 \
    -cp "$KSIM_CLASSPATH" org.kheperasim.sim.cli.Main "${args[@]}")
status=$?
if [ -f "$work/report/prairielearn/submission/results.json" ]; then
    cp "$work/report/prairielearn/submission/results.json" "$RESULTS"
else
    # The grader's own failure is not the student's: not gradable, no attempt used.
    printf '{"gradable": false, "format_errors": ["the grader could not grade this submission (khepera-sim grade exited with status %s); your instructor can see why in the grading log"]}\n' "$status" > "$RESULTS"
fi
