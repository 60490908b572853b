#!/bin/sh
# SPDX-License-Identifier: MIT
# `make test` installs the packages first and only then decides which tests
# run: a library the install provides (here libgpiod, a pkg-config file that
# an installer stand-in writes) brings its tests into that same run. Nothing
# is built: PROGRAMS and TEST_DEPS are emptied and the runner only lists.
# usage: test_make_deps.sh
set -u
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
ok() { echo "PASS $1"; }
no() { echo "FAIL $1: $2"; }
mkdir "$t/pc"
cat >"$t/deps.sh" <<EOS
#!/bin/sh
cat >"$t/pc/libgpiod.pc" <<EOP
Name: libgpiod
Description: stand-in
Version: 2.1
Cflags:
Libs:
EOP
EOS
printf '#!/bin/sh\nfor a in "$@"; do echo "test: $a"; done\n' >"$t/run.sh"
chmod +x "$t/deps.sh" "$t/run.sh"
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL -u WITH_GPIOD -u WITH_SDL2 PKG_CONFIG_LIBDIR="$t/pc" PKG_CONFIG_PATH= \
  make --no-print-directory BUILD="$t/build" DEPS_SH="$t/deps.sh" TEST_RUN="$t/run.sh" PROGRAMS= TEST_DEPS= test \
  >"$t/out" 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "^test: .*test_linux_backend" "$t/out"; then ok make_test_list_after_deps
else no make_test_list_after_deps "exit $rc, no test_linux_backend in the list: $(tail -n 3 "$t/err")"; fi
