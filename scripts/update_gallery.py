#!/usr/bin/env python3
"""Put the results of `envcrust experiment all -o DIR` into docs/experiments.md.

    build/envcrust experiment all -o out/experiments --data-dir DATA
    python3 scripts/update_gallery.py out/experiments

Each experiment's results.md (without its heading and figure links) replaces the page's block between
`<!-- results:NAME ... -->` and `<!-- /results:NAME -->`, and every figure the page shows
from docs/experiments/ is copied from DIR/NAME/ (figures the page does not show, such as the
scan's, whose data has no known licence, stay out). The hand-written "Against the paper"
paragraphs next to the blocks are not touched: read them against the new tables.
"""
import pathlib
import re
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BLOCK = re.compile(r"(<!-- results:(?P<name>[\w-]+)[^>]*-->\n)(?P<body>.*?)(\n<!-- /results:(?P=name) -->)", re.S)
FIGURE = re.compile(r"\((?:docs/)?experiments/(?P<file>[\w-]+\.png)\)")


def results_body(path: pathlib.Path) -> str:
    lines = path.read_text(encoding="utf-8").strip().split("\n")
    if lines and lines[0].startswith("## "):
        lines = lines[1:]
    # The page shows the figures itself, from docs/experiments/, above the block.
    lines = [line for line in lines if not line.startswith("![")]
    return re.sub(r"\n{3,}", "\n\n", "\n".join(lines)).strip()


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    results = pathlib.Path(sys.argv[1])
    readme_path = ROOT / "docs" / "experiments.md"
    readme = readme_path.read_text(encoding="utf-8")
    missing = []

    def replace(match: re.Match) -> str:
        source = results / match["name"] / "results.md"
        if not source.exists():
            missing.append(str(source))
            return match.group(0)
        return match.group(1) + results_body(source) + match.group(4)

    readme = BLOCK.sub(replace, readme)
    figures = {m["file"] for m in FIGURE.finditer(readme)}
    copied = 0
    for figure in sorted(figures):
        found = list(results.glob(f"*/{figure}"))
        if not found:
            missing.append(figure)
            continue
        shutil.copyfile(found[0], ROOT / "docs" / "experiments" / figure)
        copied += 1
    readme_path.write_text(readme, encoding="utf-8")
    print(f"docs/experiments.md blocks replaced from {results}; {copied} figures copied to docs/experiments")
    if missing:
        print("not found (left as they were): " + ", ".join(missing), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
