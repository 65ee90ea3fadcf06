#!/usr/bin/env python3
"""Writes the manual page fdhcert(1) from the help the program prints (`fdhcert --help` and
`fdhcert help COMMAND` for each command it lists), so that the two cannot drift: the build runs
this after linking fdhcert (cmake/man_page.cmake).

    man_page.py FDHCERT VERSION OUT

Each command is a section of its own; its option lists become tagged paragraphs, every other
paragraph of the help is kept line for line.
"""
import os
import re
import subprocess
import sys

COLUMN = 24  # the help's option column (verify/cli/src/cli.cpp, column_width)


def help_of(program, *command):
    args = [program, "help", *command] if command else [program, "--help"]
    run = subprocess.run(args, capture_output=True, text=True, env={**os.environ, "LC_ALL": "C"})
    if run.returncode != 0:
        sys.exit(f"man_page.py: {' '.join(args)} exited with {run.returncode}: {run.stderr}")
    return run.stdout


def roff(text):
    """Text as roff: backslashes and minus signs escaped, no line read as a request."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return "\n".join("\\&" + line if line.startswith((".", "'")) else line
                     for line in text.split("\n"))


def blocks(text):
    """The help's paragraphs: runs of lines between blank lines."""
    return [b.split("\n") for b in re.split(r"\n\s*\n", text.strip("\n")) if b.strip()]


def option_entries(block):
    """[(name, description)] when `block` is an option list as CLI11 prints it ("Options:", then
    entries at column 2 whose text starts at COLUMN or on the lines below), else None."""
    if len(block) < 2 or not re.fullmatch(r"\S.*:", block[0]):
        return None
    entries = []
    for line in block[1:]:
        if line.startswith(" " * COLUMN) and entries:
            entries[-1][1].append(line.strip())
        elif re.match(r"  \S", line):
            name, text = line[2:COLUMN].rstrip(), line[COLUMN:].strip()
            if len(line) > COLUMN and line[COLUMN - 1] != " ":  # a long name: its text below
                name, text = line.strip(), ""
            entries.append((name, [text] if text else []))
        else:
            return None
    if any(not text for _, text in entries):
        return None
    return [(name, " ".join(text)) for name, text in entries]


def entry_name(name):
    """`--out DIR` as bold option, italic value; `-h,--help` as two bold names."""
    parts = name.split(" ", 1)
    flags = ", ".join(f"\\fB{roff(f)}\\fR" for f in parts[0].split(","))
    return flags + (f" \\fI{roff(parts[1])}\\fR" if len(parts) > 1 else "")


def body(text):
    """A help text without its usage line, as roff paragraphs."""
    out = []
    for block in blocks(text):
        if block[0].startswith("Usage:"):
            continue
        entries = option_entries(block)
        if entries is None:
            out += [".PP", ".nf", roff("\n".join(block)), ".fi"]
            continue
        out += [".PP", f"\\fB{roff(block[0])}\\fR"]
        for name, description in entries:
            out += [".TP", entry_name(name), roff(description)]
    return out


def usage(text):
    line = next(l for l in text.split("\n") if l.startswith("Usage:"))
    return [".PP", ".B " + roff(line[len("Usage:"):].strip())]


def commands(main_help):
    """The command names of the main help's "Subcommands:" list."""
    listed = next(b for b in blocks(main_help) if b[0] == "Subcommands:")
    return [line.split()[0] for line in listed[1:] if re.match(r"  \S", line)]


def man_page(program, version):
    main_help = help_of(program)
    about = next(l for l in blocks(main_help) if not l[0].startswith("Usage:"))[0]
    about = about.split(": ", 1)[-1]
    page = [f'.TH FDHCERT 1 "" "fdhcert {version}" "User Commands"',
            ".nh", ".ad l", ".SH NAME", f"fdhcert \\- {roff(about)}",
            ".SH SYNOPSIS", ".B fdhcert", ".I command", ".RI [ options ]", ".br",
            ".B fdhcert help", ".RI [ command ]",
            ".SH DESCRIPTION", *body(main_help)]
    for command in commands(main_help):
        text = help_of(program, command)
        page += [f'.SH "COMMAND: {roff(command.upper())}"', *usage(text), *body(text)]
    page += [".SH SEE ALSO",
             "The documentation in /usr/share/doc/fdhcert and the project's docs/ folder."]
    return "\n".join(page) + "\n"


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    program, version, out = sys.argv[1:]
    text = man_page(program, version)
    tmp = f"{out}.tmp.{os.getpid()}"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, out)


if __name__ == "__main__":
    main()
