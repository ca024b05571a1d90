#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (Ubuntu): it installs a Java
# runtime with its compiler (grading compiles the students' .java files, so a JRE alone is not enough) and
# checks the simulator's jar that came in the zip.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends openjdk-17-jdk-headless
cd /autograder/source
chmod +x run_autograder
java -jar khepera-sim.jar --version
