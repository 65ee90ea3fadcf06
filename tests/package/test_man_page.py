"""fdhcert(1) against the program (ctest man_page): `man -l` renders the built page without a
warning, and every command of `fdhcert --help` and every option and positional of each command's
--help is in the rendered text, each option as a tag of its own in its command's section.
Skipped (77) without man.

    test_man_page.py FDHCERT PAGE
"""
import os
import re
import shutil
import subprocess
import sys

HEADING = re.compile(r"[A-Z][A-Za-z -]*:")  # a CLI11 list's heading: "Options:", "Positionals:"


def run(*args, **env):
    return subprocess.run(args, capture_output=True, text=True, check=True,
                          env={**os.environ, "LC_ALL": "C.UTF-8", **env})


def entries(help_text):
    """The names a help text lists: each entry of "Positionals:", each -x/--xyz of the other
    lists ("  -h,--help" gives -h and --help)."""
    names, heading = [], None
    for line in help_text.splitlines():
        if HEADING.fullmatch(line) and len(line) < 30:
            heading = line
        elif not line.strip():
            heading = None
        elif heading and re.match(r"  \S", line):
            first = line.split()[0]
            if heading == "Positionals:" or first.startswith("-"):
                names += first.split(",")
    return names


def sections(page_text):
    """The rendered page's "COMMAND: X" sections, by command."""
    parts = re.split(r"^COMMAND: (\S+)$", page_text, flags=re.M)
    return {name.lower(): text for name, text in zip(parts[1::2], parts[2::2])}


def main():
    program, page = sys.argv[1:]
    if not shutil.which("man"):
        print("skipped: no man (man-db)")
        return 77
    rendered = run("man", "--warnings", "-l", page, MANWIDTH="80")
    assert not rendered.stderr, f"man's warnings on {page}:\n{rendered.stderr}"
    text = subprocess.run(["col", "-b"], input=rendered.stdout, capture_output=True, text=True,
                          check=True).stdout
    main_help = run(program, "--help").stdout
    listed = main_help.split("Subcommands:\n", 1)[1].split("\n\n", 1)[0]
    commands = [line.split()[0] for line in listed.splitlines()]
    assert commands, "fdhcert --help lists no commands"
    for name in entries(main_help):
        assert name in text, f"the page lacks fdhcert's {name}"
    by_command = sections(text)
    checked = 0
    for command in commands:
        assert command in by_command, f"the page has no section for {command}"
        for name in entries(run(program, command, "--help").stdout):
            tag = re.compile(r"^ +(\S+, )*" + re.escape(name) + r"( |,|$)", re.M)
            assert tag.search(by_command[command]), f"the page's {command} section lacks {name}"
            checked += 1
    print(f"fdhcert(1): {len(commands)} commands, {checked} options and positionals, all there")
    return 0


if __name__ == "__main__":
    sys.exit(main())
