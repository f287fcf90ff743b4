#!/bin/sh
# `cmake --install` into a fresh prefix, then drt used as a new user would, by
# a user who is not root (as root, the script installs, then runs the rest
# as `nobody`): from the PATH, on the installed examples, with the
# documentation beside it, in a working directory and HOME that must stay
# untouched (drt writes only the files it is asked to write).
# Usage: install_as_user.sh BUILD_DIR
set -eu
build=$1
install() {
  cmake --install "$build" --prefix "$1/prefix" > "$1/install.log"
  tail -3 "$1/install.log"
  grep -q "not on your PATH" "$1/install.log" || { echo "no hint that the bin folder is not on the PATH"; exit 1; }
}
if [ "$(id -u)" -eq 0 ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  install "$work"
  chown -R nobody "$work"
  setpriv --reuid=nobody --regid=nogroup --clear-groups --reset-env \
    env DRT_INSTALL_WORK="$work" sh "$0" "$build"
  exit
fi
work=${DRT_INSTALL_WORK:-}
if [ -z "$work" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  install "$work"
fi
echo "using the installed drt as uid $(id -u)"
mkdir -p "$work/home" "$work/cwd" "$work/out"
export HOME="$work/home"
doc="$work/prefix/share/doc/drt"
for f in bin/drt lib/drt/libdrt_oiio.so share/doc/drt/README.md share/doc/drt/docs/index.md share/doc/drt/docs/golden-tests.md \
         share/doc/drt/examples/whitted.drt share/doc/drt/examples/include/materials.drt \
         share/doc/drt/grammar/drt.ebnf share/doc/drt/grammar/vim/syntax/drt.vim; do
  [ -f "$work/prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
PATH="$work/prefix/bin:/usr/bin:/bin"
export PATH
cd "$work/cwd"
drt --version
drt render "$doc/examples/declare_include.drt" -o "$work/out/declare_include.png" --width 32 --height 24 --spp 1 -q
[ -s "$work/out/declare_include.png" ] || { echo "no picture"; exit 1; }
# A golden test of the installed example, with the CI reports.
mkdir "$work/out/goldens"
cp "$doc/examples/minimal.drt" "$work/out/goldens/"
echo '{"width": 16, "height": 12, "spp": 1}' > "$work/out/goldens/minimal.golden.json"
drt test "$work/out/goldens" --update > /dev/null
drt test "$work/out/goldens" --junit "$work/out/junit.xml" --json "$work/out/results.json" --report "$work/out/report"
grep -q '<testcase name="minimal"' "$work/out/junit.xml" || { echo "no testcase in the JUnit file"; exit 1; }
left=$(find "$work/cwd" "$work/home" -mindepth 1 | head -5)
[ -z "$left" ] || { echo "drt wrote outside its outputs:"; echo "$left"; exit 1; }
echo "ok"
