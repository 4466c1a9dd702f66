#!/bin/bash
# hexant.1 is valid roff (no warning from groff) and names every
# subcommand `hexant --help` lists, nested ones too (bench error-time), as
# the formatted page shows them. Usage: man_page_test.sh HEXANT PAGE
set -u
hexant=$1
page=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
[ -s "$page" ] || fail "$page is missing or empty"

# The subcommands from --help's "Subcommands:" section, recursively.
subcommands() {  # PATH... of a command
  "$hexant" "$@" --help 2>/dev/null |
    awk '/^Subcommands:/ { on = 1; next } on && /^[^ ]/ { on = 0 } on && NF { print $1 }'
}
names=()
walk() {
  local sub
  for sub in $(subcommands "$@"); do
    names+=("$* $sub")
    walk "$@" "$sub"
  done
}
walk
[ ${#names[@]} -ge 6 ] || fail "hexant --help listed ${#names[@]} subcommands: ${names[*]}"

# Formatted: man -l (man-db) where installed, else groff; -ww shows every
# warning, and one is a failure (an unknown request, a bad escape).
if command -v groff >/dev/null; then
  groff -man -Tutf8 -ww -z "$page" 2>"$tmp/warnings"
  [ -s "$tmp/warnings" ] && { cat "$tmp/warnings"; fail "groff warns about $page"; }
fi
if command -v man >/dev/null; then
  MANWIDTH=100 man --warnings -l "$page" >"$tmp/page.txt" 2>"$tmp/warnings" || fail "man -l failed"
  [ -s "$tmp/warnings" ] && { cat "$tmp/warnings"; fail "man warns about $page"; }
elif command -v groff >/dev/null; then
  groff -man -Tutf8 -P-c -rLL=100n "$page" >"$tmp/page.txt" || fail "groff failed"
else
  sed 's/\\-/-/g' "$page" >"$tmp/page.txt"  # neither: the roff source
fi
[ -s "$tmp/page.txt" ] || fail "the formatted page is empty"
for name in "${names[@]}"; do
  # man's output holds the names as typed (\- formats as -).
  grep -q "^ *hexant ${name# }\$" "$tmp/page.txt" ||
    grep -q "^\.SS \"hexant ${name# }\"\$" "$tmp/page.txt" ||
    fail "the page has no section for 'hexant ${name# }'"
done
for flag in --version --width --spp --windows; do
  grep -q -- "$flag" "$tmp/page.txt" || fail "the page never names $flag"
done
echo "PASS: $page names ${#names[@]} subcommands:${names[*]}"
