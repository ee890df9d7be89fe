#!/usr/bin/env python3
"""The message catalogue (messages/*.msg, issue 15) against the sources:
(a) every key a call site names (msg::make("KEY", ...) / msg::text("KEY", ...)) is catalogued, and
    every catalogued key is named by some call site;
(b) each call site passes exactly the placeholders its entry's text and advice use;
(c) no diagnostic is built with a literal text: Diagnostic::info/alarm/fatal/syntax/noConvergence
    with a string literal in its text, `.withNote(` with a string literal, or a helper called with
    a message id then a literal text (fail("DEFI_GROUP_1", "the mesh ...")). The files still
    holding such sites are listed with their count in tools/lint/message-literals.allow; a file may
    not exceed its count, and a count above what is found must be lowered.
Usage: messages.py SOURCE_DIR"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
SCANNED = ["solver", "catalog", "interpreter", "tools", "messages"]


def parse_catalogue():
    entries = {}
    for path in sorted((root / "messages").glob("*.msg")):
        key = None
        for number, line in enumerate(path.read_text().splitlines(), 1):
            header = re.match(r"\[([A-Z][A-Z0-9_]*(?:\.[0-9a-z_]+)?)\] ", line)
            if header:
                key = header.group(1)
                if key in entries:
                    problems.append(f"{path.relative_to(root)}:{number}: {key} is catalogued twice")
                entries[key] = {"where": f"{path.relative_to(root)}:{number}", "patterns": []}
            elif key and (line.startswith("text: ") or line.startswith("note: ")):
                entries[key]["patterns"].append(line[6:])
    return entries


def placeholders(pattern):
    pattern = pattern.replace("{{", "").replace("}}", "")
    return set(re.findall(r"\{([A-Za-z_][A-Za-z0-9_]*)(?::[^}]*)?\}", pattern))


def skip_string(s, i):
    if s[i - 1] == "R" and (raw := re.match(r'"([^(\s]*)\(', s[i:])):  # R"delim(...)delim"
        return s.index(")" + raw.group(1) + '"', i) + len(raw.group(1)) + 2
    j = i + 1
    while s[j] != '"':
        j += 2 if s[j] == "\\" else 1
    return j + 1


def matching(s, i):
    """Index after the bracket closing the one at s[i] (the end of `s` if it cannot be read)."""
    try:
        return matching_or_raise(s, i)
    except (IndexError, ValueError):
        return len(s)


def matching_or_raise(s, i):
    depth = 0
    j = i
    while j < len(s):
        c = s[j]
        if c == '"':
            j = skip_string(s, j)
            continue
        if c == "'" and not s[j - 1].isalnum():  # a character literal, not a digit separator
            j = s.index("'", j + 3 if s[j + 1] == "\\" else j + 2) + 1
            continue
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0:
                return j + 1
        j += 1
    return len(s)


def top_level_args(s):
    try:
        return top_level_args_or_raise(s)
    except (IndexError, ValueError):
        return [s]


def top_level_args_or_raise(s):
    args, depth, start, j = [], 0, 0, 0
    while j < len(s):
        c = s[j]
        if c == '"':
            j = skip_string(s, j)
            continue
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            args.append(s[start:j].strip())
            start = j + 1
        j += 1
    args.append(s[start:].strip())
    return args


def sources():
    for top in SCANNED:
        for path in sorted((root / top).rglob("*")):
            rel = path.relative_to(root).as_posix()
            if path.suffix in (".cpp", ".hpp") and "/tests/" not in rel and "/fuzz/" not in rel:
                yield rel, path.read_text()


def strip_comments(s):
    return re.sub(r"//[^\n]*", lambda m: " " * len(m.group(0)) if '"' not in m.group(0) else
                  re.sub(r'"', " ", m.group(0)), s)


def without_catalogue_calls(s):
    """`s` without its msg::make(...) and msg::text(...) calls."""
    while (m := re.search(r"\bmsg::(make|text)\(", s)):
        s = s[:m.start()] + s[matching(s, m.end() - 1):]
    return s


class Prose:
    """A string literal holding a space, or a format string: prose, not a keyword name."""

    @staticmethod
    def search(code):
        return "fmt::format(" in code or any(" " in m.group(0) for m in re.finditer(r'"(?:[^"\\]|\\.)*"', code))


PROSE = Prose()
problems = []
catalogue = parse_catalogue()
used = set()
literal_sites = {}
sites = []  # file:line of each literal site, printed with --list
KEYARG = re.compile(r'\(\s*"([A-Z][A-Z0-9_]*(?:\.[0-9a-z_]+)?)"')
CALL = re.compile(r"\bmsg::(make|text)\(\s*\"([^\"]+)\"")
CONSTRUCT = re.compile(r"\bDiagnostic::(info|alarm|fatal|syntax|noConvergence)\(")
NOTE = re.compile(r"\.withNote\(")
# files whose fail() helpers throw something else than a diagnostic (stella sweep's SweepError)
NOT_DIAGNOSTICS = ("tools/sweep/",)
# helpers that build a diagnostic or a language error from a catalogue key
NAMED_HELPER = re.compile(r"\b(fail|failAt|failContent|report|raise|langError|throwFileError|error|notImplementedYet|notImplemented|refuse|refused)\(")
HELPER = re.compile(r"\b\w+\(\s*\"[A-Z][A-Z0-9]*(?:_[A-Z0-9]+)*_[0-9A-Z]+\"\s*,")
for rel, text in sources():
    if rel.startswith("interpreter/Diagnostics") or rel.startswith("messages/"):
        continue
    s = strip_comments(text)
    # a key chosen at run time (msg::make(rule.id, ...)) is used where its literal is written
    used.update(k for k in re.findall(r'"([A-Z][A-Z0-9_]*(?:\.[0-9a-z_]+)?)"', s) if k in catalogue)
    # every call whose first argument is a catalogued key: msg::make("KEY", {{"name", value}}, at),
    # msg::text, and helpers that forward to them (langError, throwFileError, fail...)
    for m in KEYARG.finditer(s):
        key = m.group(1)
        if key not in catalogue:
            if s[:m.start()].endswith(("msg::make", "msg::text")):
                problems.append(f"{rel}:{s.count(chr(10), 0, m.start()) + 1}: message {key} is not in messages/*.msg")
            continue
        if re.search(r"Diagnostic::\w+$", s[max(0, m.start() - 40):m.start()]):
            continue
        paren = m.start()
        args = top_level_args(s[paren + 1: matching(s, paren) - 1])
        braced = next((a for a in args[1:] if a.startswith("{")), "")
        if not braced and any(PROSE.search(a) for a in args[1:]):
            continue  # an id followed by a literal text: a site of (c), not a catalogue call
        passed = set(re.findall(r'\{\s*"([A-Za-z_][A-Za-z0-9_]*)"\s*,', braced))
        wanted = set().union(*(placeholders(p) for p in catalogue[key]["patterns"]))
        if passed != wanted:
            problems.append(f"{rel}:{s.count(chr(10), 0, m.start()) + 1}: {key} takes placeholders {sorted(wanted)} "
                            f"({catalogue[key]['where']}), the call passes {sorted(passed)}")
    count = 0
    for m in CONSTRUCT.finditer(s):
        args = top_level_args(s[m.end(): matching(s, m.end() - 1) - 1])
        if len(args) > 1 and PROSE.search(args[1]):
            count += 1
            sites.append(f"{rel}:{s.count(chr(10), 0, m.start()) + 1}")
    for m in NOTE.finditer(s):
        if PROSE.search(without_catalogue_calls(s[m.end(): matching(s, m.end() - 1) - 1])):
            count += 1
            sites.append(f"{rel}:{s.count(chr(10), 0, m.start()) + 1}")
    for m in HELPER.finditer(s):
        if s[max(0, m.start() - 5):m.start()] == "msg::":
            continue
        paren = m.start() + m.group(0).index("(")
        args = top_level_args(s[paren + 1: matching(s, paren) - 1])
        if any(PROSE.search(a) for a in args[1:] if not a.startswith("{")):
            count += 1
            sites.append(f"{rel}:{s.count(chr(10), 0, m.start()) + 1}")
    for m in NAMED_HELPER.finditer(s if not rel.startswith(NOT_DIAGNOSTICS) else ""):
        if HELPER.match(s, m.start()) or re.search(r"(void|::)\s*$", s[max(0, m.start() - 12):m.start()]):
            continue  # counted above, or a definition
        paren = m.end() - 1
        args = top_level_args(s[paren + 1: matching(s, paren) - 1])
        if any(PROSE.search(a) for a in args if not a.startswith("{")):
            count += 1
            sites.append(f"{rel}:{s.count(chr(10), 0, m.start()) + 1}")
    if count:
        literal_sites[rel] = count

for key, entry in catalogue.items():
    if key not in used:
        problems.append(f"{entry['where']}: message {key} is used by no call site: remove it")

allow_path = root / "tools" / "lint" / "message-literals.allow"
allowed = {}
for line in allow_path.read_text().splitlines():
    if line.strip() and not line.startswith("#"):
        path, count = line.split()
        allowed[path] = int(count)
for rel, count in sorted(literal_sites.items()):
    if count > allowed.get(rel, 0):
        problems.append(f"{rel}: {count} diagnostic(s) built with a literal text (allowed: {allowed.get(rel, 0)}): "
                        "put the text and its advice in messages/<area>.msg and build it with msg::make")
for rel, count in sorted(allowed.items()):
    if literal_sites.get(rel, 0) < count:
        problems.append(f"tools/lint/message-literals.allow: {rel} now has {literal_sites.get(rel, 0)} literal "
                        f"diagnostic(s), lower its count from {count}")
if "--list" in sys.argv:
    print("\n".join(sites))
print("\n".join(problems) if problems else
      f"ok: {len(catalogue)} messages, all used; {sum(literal_sites.values())} literal diagnostic site(s) "
      f"left in {len(literal_sites)} file(s) of the allow-list")
sys.exit(1 if problems else 0)
