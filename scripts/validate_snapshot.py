"""Record `sceml validate --format json` of every .xmi under examples/ and tests/, or compare two
records: what a change to validation must leave byte for byte the same.

    .venv/bin/python scripts/validate_snapshot.py record /tmp/before   # on the tree before
    .venv/bin/python scripts/validate_snapshot.py record /tmp/after    # on the tree after
    .venv/bin/python scripts/validate_snapshot.py compare /tmp/before /tmp/after

`record` runs the `sceml` next to this interpreter once per file (from the repository root, so
the paths in the reports are the same) and keeps stdout, stderr and the exit status. `compare`
lists the files whose records differ; object addresses (`0x7f...`, which pyecore's messages
about unreadable files contain) are the only thing it ignores. Exit status 1 when any differ.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SCEML = str(Path(sys.executable).with_name("sceml"))
ADDRESS = re.compile(r"0x[0-9a-f]+")


def files() -> list[Path]:
    """Every .xmi under examples/ and tests/, relative to the repository, sorted."""
    found = [*REPO.glob("examples/**/*.xmi"), *REPO.glob("tests/**/*.xmi")]
    return sorted(path.relative_to(REPO) for path in found)


def record_one(path: Path) -> str:
    ran = subprocess.run(
        [SCEML, "validate", "--format", "json", str(path)],
        cwd=REPO,
        capture_output=True,
        text=True,
    )
    return f"status {ran.returncode}\n--- stdout\n{ran.stdout}--- stderr\n{ran.stderr}"


def record(folder: Path, workers: int) -> int:
    folder.mkdir(parents=True, exist_ok=True)
    paths = files()
    with ThreadPoolExecutor(workers) as pool:
        for path, text in zip(paths, pool.map(record_one, paths), strict=True):
            (folder / (str(path).replace("/", "__") + ".txt")).write_text(text)
    print(f"{len(paths)} files recorded in {folder}")
    return 0


def compare(before: Path, after: Path) -> int:
    names = sorted({p.name for p in before.glob("*.txt")} | {p.name for p in after.glob("*.txt")})
    differ = []
    for name in names:
        old, new = before / name, after / name
        if not old.exists() or not new.exists():
            differ.append(f"{name}: only in {'after' if not old.exists() else 'before'}")
        elif ADDRESS.sub("0x", old.read_text()) != ADDRESS.sub("0x", new.read_text()):
            differ.append(f"{name}: differs")
    print("\n".join(differ) if differ else f"{len(names)} files: the same")
    return 1 if differ else 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)
    recording = commands.add_parser("record", help="record every file's report into FOLDER")
    recording.add_argument("folder", type=Path)
    recording.add_argument("--workers", type=int, default=2)
    comparing = commands.add_parser("compare", help="compare two records")
    comparing.add_argument("before", type=Path)
    comparing.add_argument("after", type=Path)
    arguments = parser.parse_args()
    if arguments.command == "record":
        return record(arguments.folder, arguments.workers)
    return compare(arguments.before, arguments.after)


if __name__ == "__main__":
    sys.exit(main())
