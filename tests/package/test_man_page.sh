#!/usr/bin/env bash
# fdhcert(1) against the program (ctest man_page): `man -l` renders the built page without a
# warning, and every command of `fdhcert --help` and every option and positional of each
# command's --help is in the rendered text. Skipped (77) without man.
#   test_man_page.sh FDHCERT PAGE
set -euo pipefail
program=$1 page=$2
command -v man >/dev/null || { echo "skipped: no man (man-db)"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -f "$page" ] || fail "no manual page $page (target fdhcert_man)"
warnings=$(LC_ALL=C.UTF-8 MANWIDTH=100 man --warnings -l "$page" 2>&1 >/dev/null) || true
[ -z "$warnings" ] || fail "man's warnings on $page: $warnings"
text=$(LC_ALL=C.UTF-8 MANWIDTH=100 man -l "$page" 2>/dev/null | col -b)
has() { grep -qF -- "$1" <<<"$text"; }

# The names of one help text's options and positionals: the first word of each entry line of a
# list (a heading such as "Options:"; "  --out DIR  ..." gives --out, "  -h,--help" gives -h and
# --help), every entry of the
# "Positionals:" list and each option (-x, --xyz) of the others.
entries() {
  awk '/^[A-Z][A-Za-z -]*:$/ && length($0) < 30 { list = $0; next } /^$/ { list = "" }
       list != "" && /^  [^ ]/ && (list == "Positionals:" || $1 ~ /^-/) { print $1 }' |
    tr ',' '\n'
}
commands=$("$program" --help | awk '/^Subcommands:$/ { on = 1; next } /^$/ { on = 0 } on { print $1 }')
[ -n "$commands" ] || fail "fdhcert --help lists no commands"
checked=0
for entry in $("$program" --help | entries); do
  has "$entry" || fail "the page lacks fdhcert's $entry"  # its DESCRIPTION
  checked=$((checked + 1))
done
for command in $commands; do
  has "COMMAND: ${command^^}" || fail "the page has no section for $command"
  section=$(awk -v head="COMMAND: ${command^^}" '$0 == head { on = 1; next } /^COMMAND: / { on = 0 }
                                                   on' <<<"$text")
  for entry in $("$program" "$command" --help | entries); do
    # As a tag of its own: at a line's start ("--out DIR", "-h, --help"), not inside a text.
    grep -qE -- "^ +([^ ]+, )*$(sed 's/[][\.*^$+?(){}|]/\\&/g' <<<"$entry")( |,|\$)" <<<"$section" ||
      fail "the page's $command section lacks $entry"
    checked=$((checked + 1))
  done
done
echo "fdhcert(1): $(wc -w <<<"$commands") commands, $checked options and positionals, all there"
