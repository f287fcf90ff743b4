#!/bin/sh
# drt test's JUnit XML read by a real consumer, Debian's python3-junitparser:
# a folder with a passing, a failing, a missing and a broken test gives one
# testcase each, with the outcome and message the reader expects.
# Usage: junit_consumer.sh DRT PYTHON3
set -eu
drt=$1
python=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene() {
  printf 'render { width 16 height 12 samples 1 seed 1 }\ncamera { location <0, 1, -4> look_at <0, 0.5, 0> }\n'
  printf 'light_source { <-3, 5, -4>, color rgb 1 }\nsphere { <0, 0.5, 0>, 0.5 pigment { color rgb %s } }\n' "$1"
}
scene 1 > "$work/pass.drt"
scene 1 > "$work/fail.drt"
"$drt" test "$work" --update > /dev/null
scene 0.5 > "$work/fail.drt"
scene 1 > "$work/missing.drt"
printf 'spere { 0, 1 }\n' > "$work/broken.drt"
echo '{}' > "$work/broken.golden.json"
status=0
"$drt" test "$work" --junit "$work/junit.xml" > /dev/null || status=$?
[ "$status" -eq 1 ] || { echo "drt test exited $status, expected 1"; exit 1; }
"$python" - "$work/junit.xml" <<'PY'
import sys
from junitparser import JUnitXml, Failure, Error
xml = JUnitXml.fromfile(sys.argv[1])
suites = list(xml)
assert len(suites) == 1, suites
suite = suites[0]
assert (suite.tests, suite.failures, suite.errors) == (4, 2, 1), (suite.tests, suite.failures, suite.errors)
found = {}
for case in suite:
    results = case.result
    found[case.name] = (type(results[0]).__name__, results[0].type, results[0].message, results[0].text) if results else None
assert found["pass"] is None, found["pass"]
kind, type_, message, text = found["fail"]
assert (kind, type_) == ("Failure", "FAIL") and "differ" in message and "RMSE" in text, found["fail"]
assert found["missing"][:2] == ("Failure", "MISSING"), found["missing"]
assert found["broken"][:2] == ("Error", "ERROR") and "spere" in found["broken"][3], found["broken"]
print("junitparser read", len(found), "testcases:", {k: (v[1] if v else "PASS") for k, v in found.items()})
PY
