#!/usr/bin/env bash
# Makes autograder.zip, the file to upload to Gradescope: setup.sh, run_autograder, grade.conf, the
# simulator's jar and any .arena files in this folder, at the zip's root.
# Run from this folder after `mvn -q -DskipTests package` in the simulator's folder:  sh make-zip.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
jar="${1:-$here/../../../sim/target/khepera-sim.jar}"
[ -f "$jar" ] || { echo "make-zip.sh: no jar at $jar; build it (mvn -q -DskipTests package) or give its path" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cp "$here/setup.sh" "$here/run_autograder" "$here/grade.conf" "$tmp/"
cp "$jar" "$tmp/khepera-sim.jar"
for a in "$here"/*.arena; do [ -e "$a" ] && cp "$a" "$tmp/"; done
rm -f "$here/autograder.zip"
(cd "$tmp" && zip -q -r "$here/autograder.zip" .)
echo "wrote $here/autograder.zip"
