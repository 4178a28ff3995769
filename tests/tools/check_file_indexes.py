#!/usr/bin/env python3
"""Every source file of the product over 400 lines opens with an index of its sections that matches it.

The index is a comment near the top: `// Sections: 1. first  2. second ...` (it may go on over the
comment lines after it); each section opens with a heading `// ---- N. title ----...`. The test
holds the index to the headings: the same numbers and titles, in the same order.

usage: check_file_indexes.py SOURCE_DIR
"""
import re
import sys
from pathlib import Path

LIMIT = 400
FOLDERS = ("geometry", "converter", "viewer")
HEADING = re.compile(r"^\s*// ---- (\d+)\. (.+?) -+\s*$")
ITEM = re.compile(r"(\d+)\.\s+(.+?)(?=\s{2,}\d+\.\s|$)")


def index_of(lines):
    """The (number, title) pairs the file's opening index lists, or None when it has none."""
    for i, line in enumerate(lines[:40]):
        at = line.find("Sections:")
        if not line.startswith("//") or at < 0:
            continue
        text = line[at + len("Sections:"):]
        for more in lines[i + 1:]:
            body = more[2:].strip() if more.startswith("//") else None
            if not body or not re.match(r"\d+\.\s", body):
                break
            text += "  " + body
        return [(int(n), t.strip()) for n, t in ITEM.findall(text.strip())]
    return None


def main():
    root = Path(sys.argv[1])
    problems = []
    checked = 0
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".cpp", ".h") or not path.is_file():
                continue
            lines = path.read_text(encoding="utf-8").splitlines()
            if len(lines) <= LIMIT:
                continue
            checked += 1
            name = path.relative_to(root)
            index = index_of(lines)
            headings = [(int(m.group(1)), m.group(2).strip()) for m in map(HEADING.match, lines) if m]
            if index is None:
                problems.append(f"{name}: {len(lines)} lines and no `// Sections:` index at the top")
            elif index != headings:
                problems.append(f"{name}: the index lists {index}, the headings are {headings}")
            elif [n for n, _ in index] != list(range(1, len(index) + 1)):
                problems.append(f"{name}: sections not numbered 1, 2, 3, ...: {index}")
    for p in problems:
        print(p)
    print(f"{checked} files over {LIMIT} lines, {len(problems)} without a matching index")
    return 1 if problems or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
