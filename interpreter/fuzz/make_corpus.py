#!/usr/bin/env python3
"""Makes the malformed seed corpus of the interpreter fuzzer (interpreter/fuzz/corpus/) by
mutating the language corpus (interpreter/corpus/*.comm) with a fixed random seed: deleted or
inserted characters, truncations, swapped or duplicated lines, broken indentation, unbalanced
brackets and quotes, deep nesting. Run it from anywhere; it rewrites the folder."""
import pathlib
import random

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = HERE.parent / "corpus"
OUT = HERE / "corpus"
SPECIAL = list("()[]{}:'\"\\\t\n#=,.%*;@$!`") + ["'''", '"""', "f'{", "**", "//", "\r", "\x00", "é"]


def mutate(text, rng):
    kind = rng.randrange(10)
    lines = text.split("\n")
    if kind == 0 and text:  # delete a run of characters
        at = rng.randrange(len(text))
        return text[:at] + text[at + rng.randint(1, 6):]
    if kind == 1:  # insert special characters
        at = rng.randrange(len(text) + 1)
        return text[:at] + "".join(rng.choice(SPECIAL) for _ in range(rng.randint(1, 3))) + text[at:]
    if kind == 2 and text:  # truncate
        return text[: rng.randrange(len(text))]
    if kind == 3 and len(lines) > 2:  # swap two lines
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
        return "\n".join(lines)
    if kind == 4 and lines:  # duplicate a line with a changed indentation
        i = rng.randrange(len(lines))
        lines.insert(i, rng.choice(["  ", "\t", "        ", ""]) + lines[i].lstrip())
        return "\n".join(lines)
    if kind == 5:  # deep or unbalanced nesting
        depth = rng.choice([50, 199, 201, 400])
        return text + "\nx = " + "(" * depth + "1" + ")" * rng.choice([depth, depth - 1, 0]) + "\n"
    if kind == 6 and lines:  # drop all indentation of a block
        return "\n".join(l.lstrip() if rng.random() < 0.5 else l for l in lines)
    if kind == 7 and text:  # replace a character by a quote or bracket
        at = rng.randrange(len(text))
        return text[:at] + rng.choice("'\"([{}])") + text[at + 1:]
    if kind == 8:  # a runtime trap appended
        return text + "\n" + rng.choice([
            "while True:\n    pass\n", "x = [0] * 10**9\n", "def f():\n    return f()\nf()\n",
            "s = 'a' * 10**10\n", "t = ()\nfor i in range(100000):\n    t = (t,)\n",
            "print(1 / 0)\n", "print('%999999d' % 1)\n", "x = 2 ** 63\n", "import os\n",
            "L = []\nL.append(L)\nprint(L)\n", "F = FORMULE(VALE='sqrt(', NOM_PARA='X')\n",
            "print(f'{1:{2}}')\n", "x = -9223372036854775807 - 1\nprint(x // -1)\n",
        ])
    # repeat a line many times
    if lines:
        i = rng.randrange(len(lines))
        lines[i:i] = [lines[i]] * rng.randint(2, 40)
    return "\n".join(lines)


def main():
    rng = random.Random(20261122)
    OUT.mkdir(exist_ok=True)
    for old in OUT.glob("*.comm"):
        old.unlink()
    count = 0
    for path in sorted(SOURCE.glob("*.comm")):
        text = path.read_text(encoding="utf-8")
        for k in range(3):
            mutated = text
            for _ in range(rng.randint(1, 3)):
                mutated = mutate(mutated, rng)
            (OUT / f"{path.stem}_{k}.comm").write_text(mutated[:4096], encoding="utf-8", newline="")
            count += 1
    print(f"{count} files written to {OUT}")


if __name__ == "__main__":
    main()
