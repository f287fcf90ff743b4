#!/bin/sh
# .ci/setup run by a user who is not root and has no sudo, with a package
# missing: it names the packages and the command an administrator runs, exits
# 1, and builds nothing. dpkg-query, id and sudo are stand-ins on the PATH.
# Usage: setup_without_sudo.sh SOURCE_DIR
set -eu
source_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin"
cat > "$work/bin/dpkg-query" <<'STUB'
#!/bin/sh
# Every package is installed except Embree and junitparser.
for last; do :; done
case "$last" in libembree-dev|python3-junitparser) exit 1 ;; esac
printf 'install ok installed'
STUB
printf '#!/bin/sh\necho 1000\n' > "$work/bin/id"
printf '#!/bin/sh\necho "sudo: a password is required" >&2\nexit 1\n' > "$work/bin/sudo"
printf '#!/bin/sh\necho "cmake must not run" >&2\nexit 99\n' > "$work/bin/cmake"
chmod +x "$work/bin/"*
mkdir "$work/src"
mkdir "$work/src/.ci"
cp "$source_dir/.ci/setup" "$work/src/.ci/setup"
status=0
PATH="$work/bin:$PATH" bash "$work/src/.ci/setup" < /dev/null > "$work/out" 2> "$work/err" || status=$?
cat "$work/err"
[ "$status" -eq 1 ] || { echo "exit status $status, expected 1"; exit 1; }
grep -q "libembree-dev python3-junitparser" "$work/err" || { echo "the missing packages are not listed"; exit 1; }
grep -q "apt-get install --no-install-recommends libembree-dev python3-junitparser" "$work/err" ||
  { echo "no command for the administrator"; exit 1; }
if grep -q "cmake must not run" "$work/err"; then echo "it went on to build"; exit 1; fi
[ ! -e "$work/src/build" ] || { echo "a build folder was made"; exit 1; }
echo "ok"
