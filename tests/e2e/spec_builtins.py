#!/usr/bin/env python3
"""runtime/LANGUAGE_SPEC.md's overview of the built-ins keeps up with the registration table: every
function and constant `hlrscript help reference` prints (the table BUILTINS.md and `:help` come from) is
named in the overview, and every call-like name the overview shows in backticks is a built-in.

usage: spec_builtins.py HLRSCRIPT LANGUAGE_SPEC.md
"""
import re
import subprocess
import sys


def main():
    hlrscript, spec_path = sys.argv[1], sys.argv[2]
    reference = subprocess.run([hlrscript, "help", "reference"], capture_output=True, text=True, check=True).stdout
    functions = reference.split("## Functions and constants", 1)[1]
    builtins = set(re.findall(r"^`([a-z_][a-z0-9_]*)", functions, re.M))
    if len(builtins) < 50:
        sys.exit(f"only {len(builtins)} built-ins read from 'help reference': the format changed?")
    spec = open(spec_path).read()
    overview = spec.split("## Built-ins", 1)[1].split("\n## ", 1)[0]
    # Names as the overview writes them: in code spans, alone or before '(' (a space-separated list of
    # names in one span counts each).
    named = set()
    for span in re.findall(r"`([^`]+)`", overview):
        for word in re.findall(r"(?<![\w.:\"])([a-z_][a-z0-9_]*)(?=\(|\s|$|,)", span):
            named.add(word)
    missing = sorted(b for b in builtins if b not in named)
    called = set()
    for span in re.findall(r"`([^`]+)`", overview):
        called.update(re.findall(r"(?<![\w.:\"])([a-z_][a-z0-9_]*)\(", span))
    unknown = sorted(c for c in called if c not in builtins)
    problems = []
    if missing:
        problems.append("built-ins missing from LANGUAGE_SPEC.md's overview: " + ", ".join(missing))
    if unknown:
        problems.append("LANGUAGE_SPEC.md's overview calls what is not a built-in: " + ", ".join(unknown))
    if problems:
        sys.exit("\n".join(problems))
    print(f"{len(builtins)} built-ins, all in the overview")


if __name__ == "__main__":
    main()
