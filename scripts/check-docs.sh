#!/usr/bin/env bash
# Runs doxygen over the public headers (Doxyfile: include/cvms) and reports
# every undocumented public declaration or documentation error.
#
# First, without doxygen, it runs scripts/check-words.sh (no process words in
# the tracked files) and checks that the umbrella header cvms/cvms.hpp
# includes exactly the headers directly in include/cvms/ (not those of its
# subfolders); a hit or a mismatch always fails.
#
# Installs doxygen with apt-get when it is missing and we are root; otherwise
# skips with a note. Reports but does not fail, unless CVMS_DOCS_STRICT=1
# (as .ci/run sets it): then any warning, or a missing doxygen, fails the
# check. HTML goes to build/docs/html.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/check-words.sh

expected=$(cd include/cvms && ls -- *.hpp | grep -vx 'cvms.hpp' | sed 's|^|cvms/|' | sort)
included=$(sed -n 's|^#include "\(cvms/[^"]*\.hpp\)"$|\1|p' include/cvms/cvms.hpp | sort)
if [ "$expected" != "$included" ]; then
  echo "docs: include/cvms/cvms.hpp must include every header in include/cvms/ and no other"
  diff <(printf '%s\n' "$expected") <(printf '%s\n' "$included") | sed -n 's/^< /  missing: /p; s/^> /  extra:   /p' || true
  exit 1
fi
echo "docs: cvms/cvms.hpp includes all $(printf '%s\n' "$expected" | wc -l) public headers"

if ! command -v doxygen >/dev/null; then
  if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null; then
    echo "cvms: installing doxygen" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends doxygen >/dev/null
  else
    echo "docs: doxygen not installed, check skipped (sudo apt-get install -y doxygen)"
    [ "${CVMS_DOCS_STRICT:-0}" = 1 ] && exit 1
    exit 0
  fi
fi

mkdir -p build/docs
log=build/docs/warnings.log
rm -f "$log"
# The script decides about failing, so doxygen itself must not stop early.
status=0
{ cat Doxyfile; echo "WARN_AS_ERROR = NO"; } | doxygen - >build/docs/doxygen.out 2>&1 || status=$?
if [ "$status" -ne 0 ]; then
  echo "docs: doxygen failed (exit $status):"
  cat build/docs/doxygen.out
  exit 1
fi

warnings=$(sed "s|^$PWD/||" "$log" || true)
count=0
[ -n "$warnings" ] && count=$(printf '%s\n' "$warnings" | wc -l)

if [ "$count" -eq 0 ]; then
  echo "docs: every public declaration in include/cvms is documented"
  exit 0
fi
echo "docs: $count doxygen warnings in include/cvms (undocumented or malformed docs); per header:"
printf '%s\n' "$warnings" | sed -n 's/^\(include\/cvms\/[^:]*\):.*/\1/p' | sort | uniq -c | sed 's/^/  /'
if [ "${CVMS_DOCS_STRICT:-0}" = 1 ]; then
  printf '%s\n' "$warnings" | sed 's/^/  /'
  echo "docs: FAILED (CVMS_DOCS_STRICT=1)"
  exit 1
fi
echo "  first ones (all: $log, or CVMS_DOCS_STRICT=1 scripts/check-docs.sh):"
printf '%s\n' "$warnings" | sed -n '1,25s/^/    /p'
echo "docs: reported only; set CVMS_DOCS_STRICT=1 to fail on these"
