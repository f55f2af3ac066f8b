#!/usr/bin/env python3
"""Keeps the editor grammars (editors/) in step with the language.

usage: check_keywords.py HLRSCRIPT SOURCE_DIR

The language's words come from where the language is defined, not from a copy:
  - every keyword of lang/grammar.hpp (each `key< TAO_PEGTL_STRING( "word" ) >`, the reserved ones
    from its `reserved` rule), including keyword-like rules such as `frames`, `hidden`, `dashed`;
  - the statements and the built-in functions and constants that `HLRSCRIPT help reference` prints
    (runtime/BUILTINS.md is that output);
  - the names bound before each frame (runtime/eval/evaluator.cpp, `frame_globals->define("...")`).
Then, for the TextMate grammar (editors/hlrscript.tmLanguage.json) and the Vim syntax
(editors/vim/syntax/hlrscript.vim):
  - each word is highlighted as what it is (a keyword, a built-in function, a constant, a frame
    name) by at least one pattern, and no pattern names a word the language does not have;
  - the grammar is well formed: JSON, every `#include` resolves, every regex compiles with Python's
    re (the grammar keeps to the subset re shares with Oniguruma), it converts to a plist (Sublime),
    and the VS Code extension carries the same file;
  - tests/editors/sample.hls (checked by `hlrscript check`, so it is real hlrscript) is highlighted by
    both: its `#@ WORD:KIND` notes say what each contextual word must be there. The TextMate grammar
    runs in a small interpreter of its rules below; Vim runs headless when it is installed.
"""
import json
import os
import plistlib
import re
import shutil
import subprocess
import sys
import tempfile

FAILURES = []


def fail(message):
    FAILURES.append(message)


# ---- the language -------------------------------------------------------------------------------

def grammar_words(grammar_hpp):
    """All keywords of the PEGTL grammar, and the reserved ones."""
    text = open(grammar_hpp, encoding="utf-8").read()
    words = set(re.findall(r'key<\s*TAO_PEGTL_STRING\(\s*"(\w+)"\s*\)\s*>', text))
    rule_word = dict(re.findall(r'struct\s+(key_\w+)\s*:\s*key<\s*TAO_PEGTL_STRING\(\s*"(\w+)"', text))
    reserved_rule = re.search(r'struct\s+reserved\s*:\s*(?:sor|any_word)<(.*?)>\s*\{\}', text, re.S)
    if not reserved_rule:
        fail("lang/grammar.hpp: no `struct reserved : any_word< ... >` rule found")
        return words, set()
    reserved = {rule_word[name] for name in re.findall(r'key_\w+', reserved_rule.group(1))}
    return words, reserved


def reference_words(hlrscript):
    """Statement keywords, built-in functions and built-in constants from `help reference`."""
    text = subprocess.run([hlrscript, "help", "reference"], check=True, capture_output=True,
                          text=True, timeout=60).stdout
    statements, functions, constants = set(), set(), set()
    section = None
    entry = None
    for line in text.splitlines():
        if line.startswith("## "):
            section = line[3:].strip()
        elif section == "Statements" and line.startswith("- `"):
            statements.add(re.match(r"- `(\w+)", line).group(1))
        elif line.startswith("### "):
            entry = line[4:].strip()
            functions.add(entry)
        elif entry and "(a built-in constant)" in line:
            functions.discard(entry)
            constants.add(entry)
    return statements, functions, constants


def frame_names(evaluator_cpp):
    text = open(evaluator_cpp, encoding="utf-8").read()
    return set(re.findall(r'frame_globals->define\("(\w+)"', text))


# ---- what a highlighted word is -----------------------------------------------------------------

KEYWORD_LINKS = {"Statement", "Conditional", "Repeat", "Include", "Keyword", "StorageClass", "Boolean",
                 "Operator"}
VIM_GROUP_KIND = {"hlrBuiltin": "function", "hlrConstant": "constant", "hlrFrameVar": "frame",
                  "hlrVertexDecl": "vertex", "hlrFaceItem": "vertex"}


def tm_kind(scopes):
    """The kind of a word from its TextMate scopes, innermost first; plain text is a name."""
    for scope in reversed(scopes):
        for prefix, kind in (("comment", "comment"), ("keyword.", "keyword"), ("storage.", "keyword"),
                             ("constant.language.", "keyword"), ("support.function", "function"),
                             ("support.constant", "constant"), ("variable.language", "frame"),
                             ("variable.other.vertex", "vertex"), ("string", "string"),
                             ("entity.name", "name"), ("variable.", "name"), ("constant.other", "name")):
            if scope.startswith(prefix):
                return kind
    return "name"


def vim_kind(group, link):
    if group in VIM_GROUP_KIND:
        return VIM_GROUP_KIND[group]
    if link == "Comment":
        return "comment"
    if link == "String":
        return "string"
    return "keyword" if link in KEYWORD_LINKS else "name"


# ---- regex words --------------------------------------------------------------------------------

def onig_words(regex):
    """(word, capture-group chain, in-lookaround) for each literal word of an Oniguruma/re regex.

    Escapes (\\b, \\s) and character classes are skipped; `(?:`, `(?=`, `(?!`, `(?<=`, `(?<!` open
    groups that do not capture, the last four looking around (a word there is not highlighted).
    """
    out, stack, group_count, i = [], [], 0, 0
    while i < len(regex):
        c = regex[i]
        if c == "\\":
            i += 2
            continue
        if c == "[":
            i += 1
            while i < len(regex) and regex[i] != "]":
                i += 2 if regex[i] == "\\" else 1
            i += 1
            continue
        if c == "(":
            look = re.match(r"\((?:\?(?:<?[=!]|:))?", regex[i:]).group(0)
            if look == "(":
                group_count += 1
                stack.append(("capture", group_count))
            else:
                stack.append(("look" if look != "(?:" else "group", None))
            i += len(look)
            continue
        if c == ")":
            stack.pop()
            i += 1
            continue
        word = re.match(r"[A-Za-z_][A-Za-z0-9_]*", regex[i:])
        if word:
            chain = [n for kind, n in stack if kind == "capture"]
            out.append((word.group(0), chain, any(kind == "look" for kind, _ in stack)))
            i += len(word.group(0))
            continue
        number = re.match(r"[0-9]+", regex[i:])
        i += len(number.group(0)) if number else 1
    return out


def vim_pattern_words(pattern):
    """Literal words of a Vim pattern: escapes (\\<, \\%(, \\@<=, \\_s, \\zs) and collections skipped."""
    i, text = 0, []
    while i < len(pattern):
        c = pattern[i]
        if c == "\\":
            escape = re.match(r"\\(?:_.|z.|%\(|@\d*<?[=!]|@>|.)", pattern[i:]).group(0)
            text.append(" ")
            i += len(escape)
        elif c == "[" and "]" in pattern[i + 1:]:
            i += 1
            while i < len(pattern) and pattern[i] != "]":
                i += 2 if pattern[i] == "\\" else 1
            i += 1
            text.append(" ")
        else:
            text.append(c)
            i += 1
    return re.findall(r"(?<![A-Za-z0-9_])[A-Za-z_][A-Za-z0-9_]*", "".join(text))


# ---- the TextMate grammar -----------------------------------------------------------------------

REGEX_KEYS = ("match", "begin", "end", "while")


class TextMate:
    def __init__(self, path):
        self.grammar = json.load(open(path, encoding="utf-8"))
        self.repository = self.grammar.get("repository", {})
        self.compiled = {}

    def rules(self):
        """Every rule object of the grammar, with where it is."""
        found = []

        def walk(rule, where):
            if isinstance(rule, dict):
                found.append((rule, where))
                for n, child in enumerate(rule.get("patterns", [])):
                    walk(child, f"{where}/patterns[{n}]")
        walk(self.grammar, "")
        for name, rule in self.repository.items():
            walk(rule, f"#{name}")
        return found

    def check_structure(self):
        for key in ("scopeName", "patterns", "repository", "fileTypes"):
            if key not in self.grammar:
                fail(f"tmLanguage: no '{key}'")
        if self.grammar.get("scopeName") != "source.hlrscript" or self.grammar.get("fileTypes") != ["hls"]:
            fail("tmLanguage: scopeName must be source.hlrscript and fileTypes [\"hls\"]")
        for rule, where in self.rules():
            include = rule.get("include")
            if include and include.startswith("#") and include[1:] not in self.repository:
                fail(f"tmLanguage {where}: include '{include}' names no repository entry")
            for key in REGEX_KEYS:
                if key in rule:
                    try:
                        re.compile(rule[key])
                    except re.error as error:
                        fail(f"tmLanguage {where}: {key} /{rule[key]}/ does not compile: {error}")
        try:
            plistlib.dumps(self.grammar)
        except (TypeError, OverflowError) as error:
            fail(f"tmLanguage: does not convert to a plist for Sublime Text: {error}")

    def regex(self, source):
        if source not in self.compiled:
            try:
                self.compiled[source] = re.compile(source)
            except re.error:  # reported by check_structure; here it matches nothing
                self.compiled[source] = re.compile(r"(?!)")
        return self.compiled[source]

    def word_kinds(self):
        """word -> set of kinds it is highlighted as (None: named only, e.g. in a lookahead)."""
        kinds = {}
        for rule, _ in self.rules():
            for key in REGEX_KEYS:
                if key not in rule:
                    continue
                captures = rule.get({"begin": "beginCaptures", "end": "endCaptures"}.get(key, ""),
                                    rule.get("captures", {}))
                for word, chain, looking in onig_words(rule[key]):
                    scopes = [rule["name"]] if "name" in rule else []
                    scopes += [captures[str(n)]["name"] for n in chain if captures.get(str(n), {}).get("name")]
                    kind = None if looking or not scopes else tm_kind(scopes)
                    kinds.setdefault(word, set()).add(kind)
        return kinds

    # A small interpreter of the rules, enough to read the scopes of a word: the earliest match wins,
    # the end pattern before the patterns on a tie, then the patterns in order (TextMate's rules).
    def expand(self, patterns):
        out = []
        for rule in patterns:
            include = rule.get("include")
            if include == "$self" or include == "$base":
                out += self.expand(self.grammar["patterns"])
            elif include:
                entry = self.repository.get(include[1:])
                if entry is None:  # reported by check_structure
                    continue
                out += self.expand(entry["patterns"]) if "match" not in entry and "begin" not in entry else [entry]
            elif "match" in rule or "begin" in rule:
                out.append(rule)
            else:
                out += self.expand(rule.get("patterns", []))
        return out

    def tokenize(self, lines):
        """Per line, per character: the list of scopes."""
        stack = [(self.grammar, None, [])]  # (rule, end regex, scopes inside it)
        result = []
        for line in lines:
            text = line + "\n"
            scopes = [None] * len(text)
            pos, steps = 0, 0
            while pos < len(text) and steps < 10000:
                steps += 1
                rule, end, inside = stack[-1]
                best, best_rule = (end.search(text, pos) if end else None), None
                for candidate in self.expand(rule.get("patterns", [])):
                    m = self.regex(candidate.get("match", candidate.get("begin"))).search(text, pos)
                    if m and (best is None or m.start() < best.start()):
                        best, best_rule = m, candidate
                if best is None:
                    break
                for k in range(pos, best.start()):
                    scopes[k] = inside
                if best_rule is None:  # the region's end
                    self.paint(scopes, best, inside, rule.get("endCaptures", rule.get("captures", {})))
                    stack.pop()
                elif "match" in best_rule:
                    here = inside + ([best_rule["name"]] if "name" in best_rule else [])
                    self.paint(scopes, best, here, best_rule.get("captures", {}))
                else:
                    here = inside + ([best_rule["name"]] if "name" in best_rule else [])
                    self.paint(scopes, best, here, best_rule.get("beginCaptures", best_rule.get("captures", {})))
                    stack.append((best_rule, self.regex(best_rule["end"]), here))
                pos = best.end() + (1 if best.end() == best.start() and best_rule and "match" in best_rule else 0)
            for k in range(len(text)):
                scopes[k] = scopes[k] if scopes[k] is not None else stack[-1][2]
            result.append(scopes)
        return result

    @staticmethod
    def paint(scopes, m, base, captures):
        for k in range(m.start(), m.end()):
            scopes[k] = list(base)
        for n in sorted(captures, key=int):
            if int(n) <= m.re.groups and m.start(int(n)) >= 0 and "name" in captures[n]:
                for k in range(m.start(int(n)), m.end(int(n))):
                    scopes[k] = scopes[k] + [captures[n]["name"]]


# ---- the Vim syntax -----------------------------------------------------------------------------

VIM_OPTIONS = {"contained", "skipwhite", "skipnl", "skipempty", "transparent", "fold", "display", "extend",
               "excludenl", "keepend", "oneline", "concealends", "conceal"}


def vim_syntax(path):
    """word -> set of kinds, from `syn keyword/match/region` and the `hi def link`s."""
    lines = []
    for line in open(path, encoding="utf-8"):
        if re.match(r"\s*\\", line) and lines:
            lines[-1] += re.sub(r"^\s*\\", "", line.rstrip("\n"))
        else:
            lines.append(line.rstrip("\n"))
    links = dict(re.findall(r"^hi def link (\w+) (\w+)", "\n".join(lines), re.M))
    items = []  # (group, words)
    for line in lines:
        m = re.match(r"syn keyword (\w+) (.*)$", line)
        if m:
            words = [w for w in m.group(2).split() if "=" not in w and w not in VIM_OPTIONS]
            items.append((m.group(1), words))
            continue
        m = re.match(r"syn (match|region) (\w+) (.*)$", line)
        if not m:
            continue
        rest = m.group(3)
        starts = [rest[0:]] if m.group(1) == "match" else \
            [rest[p.end():] for p in re.finditer(r"\b(?:start|skip|end)=", rest)]
        for text in starts:
            delimiter, i = text[0], 1
            while i < len(text) and text[i] != delimiter:
                i += 2 if text[i] == "\\" else 1
            items.append((m.group(2), vim_pattern_words(text[1:i])))
    kinds = {}
    for group, words in items:
        if words and group not in links:
            fail(f"vim: group {group} has no `hi def link`")
        for word in words:
            kinds.setdefault(word, set()).add(vim_kind(group, links.get(group, "")))
    return kinds, links


VIM_PROBE = r"""
let s:out = ['filetype=' . &filetype, 'commentstring=' . &commentstring,
      \ 'syntax=' . get(b:, 'current_syntax', ''), 'errmsg=' . v:errmsg]
for s:entry in readfile($HLR_PROBE_IN)
  let [s:lnum, s:col] = split(s:entry)
  let s:id = synID(s:lnum, s:col, 1)
  call add(s:out, join([s:lnum, s:col, synIDattr(s:id, 'name')]))
endfor
call writefile(s:out, $HLR_PROBE_OUT)
qall!
"""


def vim_probe(vim, runtime_dir, sample, positions, work):
    """Vim's syntax group at each (line, column), 1-based; and the buffer's settings."""
    probe, probe_in, probe_out = (os.path.join(work, n) for n in ("probe.vim", "in.txt", "out.txt"))
    open(probe, "w").write(VIM_PROBE)
    open(probe_in, "w").write("".join(f"{l} {c}\n" for l, c in positions))
    env = dict(os.environ, HLR_PROBE_IN=probe_in, HLR_PROBE_OUT=probe_out)
    run = subprocess.run([vim, "-Nu", "NONE", "-i", "NONE", "-n", "-es", "--cmd", f"set rtp^={runtime_dir}",
                          "-c", "filetype plugin on", "-c", "syntax on", "-c", f"edit {sample}",
                          "-c", f"source {probe}"], env=env, capture_output=True, text=True, timeout=60)
    if not os.path.exists(probe_out):
        fail(f"vim did not run the probe (status {run.returncode}): {run.stdout}{run.stderr}")
        return {}, {}
    out = open(probe_out).read().splitlines()
    settings = dict(line.split("=", 1) for line in out[:4])
    groups = {}
    for line in out[4:]:
        parts = line.split(" ")
        groups[(int(parts[0]), int(parts[1]))] = parts[2] if len(parts) > 2 else ""
    return settings, groups


# ---- the checks ---------------------------------------------------------------------------------

def sample_notes(lines):
    """(line, column, word, kind) for each `#@ WORD[@N]:KIND` note, 1-based."""
    notes = []
    for n, line in enumerate(lines, 1):
        if "#@ " not in line:
            continue
        code, _, note_text = line.partition("#@ ")
        for note in note_text.split():
            word, kind = note.split(":")
            word, _, nth = word.partition("@")
            found = list(re.finditer(rf"(?<![A-Za-z0-9_]){word}(?![A-Za-z0-9_])", code))
            if len(found) < int(nth or 1):
                fail(f"sample.hls:{n}: note '{note}': no such word in the line")
                continue
            notes.append((n, found[int(nth or 1) - 1].start() + 1, note, kind))
    return notes


def check_words(what, kinds, expected, language):
    for word, want in sorted(expected.items()):
        if want not in kinds.get(word, set()):
            got = ", ".join(sorted(k or "unhighlighted" for k in kinds.get(word, set()))) or "absent"
            fail(f"{what}: '{word}' must be highlighted as {want} (found: {got})")
    for word in sorted(set(kinds) - language):
        fail(f"{what}: '{word}' is not a word of the language (stale or misspelt)")


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    hlrscript, source = argv[1], argv[2]
    editors = os.path.join(source, "editors")

    keywords, reserved = grammar_words(os.path.join(source, "lang", "grammar.hpp"))
    statements, functions, constants = reference_words(hlrscript)
    frames = frame_names(os.path.join(source, "runtime", "eval", "evaluator.cpp"))
    # A parse that found nothing would make every check below pass: refuse it.
    for name, found, least in (("keywords", keywords, 30), ("reserved words", reserved, 20),
                               ("statements", statements, 15), ("functions", functions, 50),
                               ("constants", constants, 1), ("frame names", frames, 4)):
        if len(found) < least:
            fail(f"found only {len(found)} {name} in the language's sources; has their format changed?")
    if not statements <= keywords:
        fail(f"statements that are no keyword of lang/grammar.hpp: {sorted(statements - keywords)}")
    expected = {w: "keyword" for w in keywords | statements}
    expected.update({w: "function" for w in functions})
    expected.update({w: "constant" for w in constants})
    expected.update({w: "frame" for w in frames - keywords})  # `frames` is also a clause keyword
    language = set(expected) | frames

    grammar_path = os.path.join(editors, "hlrscript.tmLanguage.json")
    tm = TextMate(grammar_path)
    tm.check_structure()
    check_words("tmLanguage", tm.word_kinds(), expected, language)
    vim_kinds, vim_links = vim_syntax(os.path.join(editors, "vim", "syntax", "hlrscript.vim"))
    check_words("vim syntax", vim_kinds, expected, language)

    # VS Code: the extension folder is self-contained (it is copied whole), so it carries a copy.
    vscode = os.path.join(editors, "vscode")
    package = json.load(open(os.path.join(vscode, "package.json"), encoding="utf-8"))
    for grammar in package["contributes"]["grammars"]:
        copy = os.path.join(vscode, grammar["path"])
        if open(copy, "rb").read() != open(grammar_path, "rb").read():
            fail(f"{copy} differs from editors/hlrscript.tmLanguage.json: copy it over")
        if grammar["scopeName"] != "source.hlrscript":
            fail("package.json: the grammar's scopeName must be source.hlrscript")
    for language_entry in package["contributes"]["languages"]:
        configuration = json.load(open(os.path.join(vscode, language_entry["configuration"]), encoding="utf-8"))
        if configuration.get("comments", {}).get("lineComment") != "#":
            fail("language-configuration.json: the line comment is '#'")
        if ".hls" not in language_entry.get("extensions", []):
            fail("package.json: the language must claim .hls")
    ftdetect = open(os.path.join(editors, "vim", "ftdetect", "hlrscript.vim"), encoding="utf-8").read()
    if "*.hls" not in ftdetect or "filetype=hlrscript" not in ftdetect:
        fail("vim ftdetect: *.hls must set filetype=hlrscript")

    # The sample: real hlrscript, highlighted as its notes say.
    sample = os.path.join(source, "tests", "editors", "sample.hls")
    check = subprocess.run([hlrscript, "check", sample], capture_output=True, text=True, timeout=120)
    if check.returncode != 0:
        fail(f"sample.hls is not a valid script:\n{check.stderr}")
    lines = open(sample, encoding="utf-8").read().splitlines()
    notes = sample_notes(lines)
    if len(notes) < 40:
        fail(f"sample.hls: only {len(notes)} notes")
    scopes = tm.tokenize(lines)
    for lnum, col, note, kind in notes:
        got = tm_kind(scopes[lnum - 1][col - 1])
        if got != kind:
            fail(f"tmLanguage, sample.hls:{lnum}:{col}: '{note}' highlighted as {got} "
                 f"(scopes {' '.join(scopes[lnum - 1][col - 1])})")
    vim = shutil.which("vim")
    if vim:
        with tempfile.TemporaryDirectory() as work:
            settings, groups = vim_probe(vim, os.path.join(editors, "vim"), sample,
                                         [(l, c) for l, c, _, _ in notes], work)
        want = {"filetype": "hlrscript", "commentstring": "# %s", "syntax": "hlrscript", "errmsg": ""}
        for key, value in want.items():
            if settings and settings.get(key) != value:
                fail(f"vim: {key} is '{settings.get(key)}', expected '{value}'")
        for lnum, col, note, kind in notes:
            # Kinds by the file's own `hi def link` (synIDtrans would follow String to Constant).
            group = groups.get((lnum, col), "")
            if groups and vim_kind(group, vim_links.get(group, "")) != kind:
                fail(f"vim, sample.hls:{lnum}:{col}: '{note}' highlighted as "
                     f"{vim_kind(group, vim_links.get(group, ''))} (group {group or 'none'})")
        vim_note = f"vim ran on {len(notes)} notes"
    else:
        vim_note = "vim not installed: the Vim syntax was checked statically only"

    if FAILURES:
        print("\n".join(FAILURES))
        print(f"{len(FAILURES)} problem(s)")
        return 1
    print(f"ok: {len(expected)} words ({len(reserved)} reserved, {len(keywords)} grammar keywords, "
          f"{len(functions)} functions, {len(constants)} constants), {len(notes)} sample notes; {vim_note}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
