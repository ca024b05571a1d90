#!/bin/sh
# Grades one student's copy of the assignment as the course's CI does: the course's own build file,
# arena and hidden tests are copied over the student's, then the tests run. Only src/main/java is the
# student's; whatever they changed elsewhere is replaced.
#
#   sh instructor/grade-submission.sh PATH/TO/STUDENT/PROJECT [MAVEN ARGUMENTS]
#
# The Maven arguments default to "test"; "test -Dtest='GradingTest#scoresAllThePoints'" runs one test.
# Exit status: Maven's (0 when every test run passed). Each test's result is in
# PATH/TO/STUDENT/PROJECT/target/surefire-reports/ (JUnit XML, which CI systems read), and the run of
# every failing test in target/kheperasim-runs/. Set MVN to run Maven otherwise (e.g. MVN="mvn -o").
set -eu
course=$(cd "$(dirname "$0")/.." && pwd)
student=$(cd "${1:?usage: grade-submission.sh PATH/TO/STUDENT/PROJECT [MAVEN ARGUMENTS]}" && pwd)
shift
mvn=${MVN:-mvn}

cp "$course/pom.xml" "$student/pom.xml"
mkdir -p "$student/src/test/java/assignment" "$student/src/test/resources"
cp "$course/src/test/resources/corridor.arena" "$student/src/test/resources/corridor.arena"
cp "$course/instructor/hidden-tests/assignment/"*.java "$student/src/test/java/assignment/"

cd "$student"
if [ $# -eq 0 ]; then
    set -- test
fi
# shellcheck disable=SC2086 # MVN may hold options
exec $mvn -B "$@"

