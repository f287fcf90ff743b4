#!/bin/sh
# .ci/run must run exactly the test command the README gives a new user
# (the first line of the sh block under "## Run the tests").
set -eu
root=$1
readme=$(awk '/^## Run the tests/ { section = 1 } section && /^```sh/ { getline; print; exit }' "$root/README.md")
run=$(grep -v -e '^#' -e '^set ' -e '^cd ' -e '^$' "$root/.ci/run")
if [ -z "$readme" ] || [ "$readme" != "$run" ]; then
    echo "README's test command: '$readme'"
    echo ".ci/run runs:          '$run'"
    exit 1
fi
echo "both run: $run"
