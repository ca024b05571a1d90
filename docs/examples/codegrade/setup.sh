#!/usr/bin/env bash
# CodeGrade's global setup script (runs once, cached): a JDK (grading compiles the students' .java files).
set -euo pipefail
sudo apt-get update -q
sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends openjdk-17-jdk-headless
java -jar "$FIXTURES/khepera-sim.jar" --version
