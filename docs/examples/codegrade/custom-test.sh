#!/usr/bin/env bash
# A CodeGrade custom test: grades the submission ($STUDENT) with khepera-sim grade over the arenas and
# seeds below and prints a line per run, then the line CodeGrade reads: {"tag": "points", "points": "S/M"}.
# Usage in the custom test's command field:  bash $FIXTURES/custom-test.sh "maze two-rooms" 5 60
set -u
ARENAS="${1:-maze}"
SEEDS="${2:-5}"
SECONDS_PER_RUN="${3:-60}"
HIDDEN="${4:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/hand-ins/submission"
cp -R "${STUDENT:-.}/." "$work/hand-ins/submission/"
args=(grade --submissions "$work/hand-ins" --arenas $ARENAS --seeds "$SEEDS" --seconds "$SECONDS_PER_RUN"
      --deadline "${DEADLINE:-8m}" --no-sandbox --format codegrade --out "$work/report")
if [ -n "$HIDDEN" ]; then args+=(--hidden $HIDDEN); fi
(cd "${FIXTURES:-.}" && java -Xmx160m -jar "${FIXTURES:-.}/khepera-sim.jar" "${args[@]}") > "$work/grade.log" 2>&1
out="$work/report/codegrade/submission/output.txt"
if [ ! -f "$out" ]; then
    echo "the grader could not grade this submission:"; tail -3 "$work/grade.log"; exit 1
fi
cat "$out"
# Not gradable (does not compile, refused at load): the step fails too, so CodeGrade marks it.
if head -1 "$out" | grep -q '^not gradable: '; then exit 1; fi
